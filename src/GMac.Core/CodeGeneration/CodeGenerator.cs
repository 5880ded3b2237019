using GMac.Core.CodeGeneration.Accuracy;
using GMac.Core.CodeGeneration.Cost;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>From symbolic evaluation to an optimized code block.</summary>
public static class CodeGenerator
{
    private const int HopelessFactor = 3;

    /// <summary>
    /// Evaluates the macro once per candidate form and keeps the fastest accurate one (<see cref="FormRanking"/>): up to three calls of
    /// <see cref="CodeGenerationRequest.Evaluate"/> (split with every intermediate named, split with
    /// whole statements named, joined), fewer when <see cref="CodeGenerationRequest.Join"/> fixes
    /// the form. One evaluation cannot serve all three: a recorder names intermediate values while
    /// the macro runs and later operations work on those names, so each form is a different
    /// symbolic program. The callback is the only way back into the evaluating stage; the
    /// recorders it is given are made here, with the simplifier built here.
    /// </summary>
    public static CodeGenerationResult Generate(CodeGenerationRequest request)
    {
        request = request with { Simplify = EffectiveSimplifier(request.Simplify) };
        var candidates = new List<(CodeBlock Block, JoinMode Form)>();
        var builtBlocks = new List<CodeBlock>();
        var forms = new FormMemo();
        FormTooLargeException? tooLarge = null;
        if (request.Join != JoinMode.Joined)
        {
            foreach (var statementsOnly in new[] { false, true })
            {
                var recorder = new TemporaryRecorder(request.Simplify, statementsOnly);
                var form = statementsOnly ? "split by statement" : "split by operation";
                SymbolicProgram program;
                try
                {
                    program = GenerationProfile.Time($"evaluate {form}", () => request.Evaluate(recorder));
                }
                catch (FormTooLargeException e)
                {
                    // One statement holding exp(t·log(M₀~M₁)) is too large unnamed; another form may not be.
                    tooLarge ??= e;
                    continue;
                }
                // Where every statement is one operation both recorders name the same values: the
                // second form is then the same program, and building it again would give the same block.
                var built = forms.BuiltFrom(program, recorder.Temporaries)
                    ?? GenerationProfile.Time($"build {form}", () => Build(program, recorder.Temporaries, request));
                forms.Remember(program, recorder.Temporaries, built);
                candidates.Add((forms.Optimized(built, form), JoinMode.Split));
                builtBlocks.Add(built);
            }
        }
        if (request.Join != JoinMode.Split)
        {
            SymbolicProgram? evaluated;
            try
            {
                evaluated = EvaluateJoined(request, splitFormsExist: candidates.Count > 0);
            }
            catch (FormTooLargeException e)
            {
                // Fully expanded, the outputs are too large to write (exp of a log of a product):
                // the split forms, which name intermediate values, stand.
                tooLarge ??= e;
                return Ranked(candidates, builtBlocks, tooLarge, request);
            }
            // Optimizing a fully expanded block is the slowest step; skip it when it starts far
            // costlier than a form already found (sharing rarely recovers more than that). Lowering
            // stops as soon as the part lowered so far is past that bound.
            var bestSoFar = candidates.Count == 0 ? long.MaxValue : HopelessFactor * (long)candidates.Min(c => c.Block.Statistics().Cost);
            var joined = evaluated is null ? null : BuildJoined(evaluated, request, bestSoFar, splitFormsExist: candidates.Count > 0);
            if (joined is not null)
            {
                candidates.Add((forms.Optimized(joined, "joined"), JoinMode.Joined));
                builtBlocks.Add(joined);
            }
        }
        return Ranked(candidates, builtBlocks, tooLarge, request);
    }

    private static CodeGenerationResult Ranked(List<(CodeBlock Block, JoinMode Form)> candidates, List<CodeBlock> builtBlocks,
        FormTooLargeException? tooLarge, CodeGenerationRequest request)
    {
        if (candidates.Count == 0 && tooLarge is not null)
            System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(tooLarge.InnerException!).Throw();
        GenerationProfile.Time("difference forms", () => { AddDifferenceForms(candidates, builtBlocks, request.Relations); return 0; });
        GenerationProfile.Time("origin shift forms", () => { AddOriginShiftForms(candidates); return 0; });
        AddDivisionForms(candidates);
        // The fastest accurate form wins (see FormRanking); equal estimates go to fewer operations,
        // fewer temporaries, then the joined (simplest) form.
        var ordered = candidates
            .Select((c, i) => (c.Block, c.Form, Stats: c.Block.Statistics(), Index: i))
            .OrderBy(c => c.Form == JoinMode.Joined ? 0 : 1).ThenBy(c => c.Index)
            .ToList();
        var ranking = GenerationProfile.Time("form ranking", () => FormRanking.Rank(ordered.Select(c => c.Block).ToList(), request.Relations));
        var best = ordered[ranking[0]];
        var alternative = ranking.Skip(1).Select(i => ordered[i]).FirstOrDefault(c => c.Form != best.Form);
        // signs are placed on the kept form alone: that changes no count, so no choice above
        return new CodeGenerationResult(Optimizer.Finish(best.Block), best.Stats, best.Form, alternative.Block is null ? null : alternative.Stats);
    }

    /// <summary>The joined form built; null when hopeless, or too large to expand while split forms stand.</summary>
    private static CodeBlock? BuildJoined(SymbolicProgram evaluated, CodeGenerationRequest request, long bestSoFar, bool splitFormsExist)
    {
        try
        {
            return GenerationProfile.Time("build joined", () => Build(evaluated, [], request, bestSoFar));
        }
        catch (Algebra.AlgebraException e) when (splitFormsExist && e.ExceedsLimit)
        {
            return null;
        }
    }

    /// <summary>
    /// The macro evaluated without names; null when it is too large to expand that way (a general
    /// inverse in 5D) and the split forms, which name partial results, already stand.
    /// </summary>
    private static SymbolicProgram? EvaluateJoined(CodeGenerationRequest request, bool splitFormsExist)
    {
        try
        {
            return GenerationProfile.Time("evaluate joined", () => request.Evaluate(null));
        }
        catch (Exception e) when (splitFormsExist && (e as Algebra.AlgebraException ?? e.InnerException as Algebra.AlgebraException) is { ExceedsLimit: true })
        {
            return null;
        }
    }

    /// <summary>
    /// Where the outputs move with the input positions, each form run with one position at the
    /// origin and its outputs moved back (<see cref="OriginShift"/>): the sphere through four points
    /// as the sphere through 0 and three differences, moved by the first point.
    /// </summary>
    private static void AddOriginShiftForms(List<(CodeBlock Block, JoinMode Form)> candidates)
    {
        if (candidates.Count == 0 || OriginShift.Find(candidates[0].Block) is not { } law) return;
        for (var i = candidates.Count - 1; i >= 0; i--)
        {
            var variant = Passes.ConsumerFirstOrder.Apply(Optimizer.Reduce(OriginShift.Apply(candidates[i].Block, law)));
            if (!candidates.Exists(c => c.Block.HasSameStatements(variant))) candidates.Add((variant, candidates[i].Form));
        }
    }

    /// <summary>
    /// For each form that multiplies by reciprocals, the same form dividing instead: faster where
    /// the multipliers are busier than the divider (<see cref="Passes.ReciprocalDivisionPass"/>).
    /// </summary>
    private static void AddDivisionForms(List<(CodeBlock Block, JoinMode Form)> candidates)
    {
        var pass = new Passes.ReciprocalDivisionPass();
        for (var i = candidates.Count - 1; i >= 0; i--)
        {
            var variant = pass.Run(candidates[i].Block);
            if (!ReferenceEquals(variant, candidates[i].Block) && !candidates.Exists(c => c.Block.HasSameStatements(variant)))
                candidates.Add((variant, candidates[i].Form));
        }
    }

    /// <summary>
    /// For each form that loses accuracy on the probe and reads points, the same form with every
    /// value that moves with the points written over their differences to one of them. It joins the
    /// candidates where it costs no more operations than the form it comes from (the moment of a
    /// line whose direction q − p is computed anyway), or where another form is accurate: then it
    /// may be a faster way to that accuracy (v1 × (v2 − v1) ahead of a division in Gram–Schmidt),
    /// and the ranking decides; or where the points are positions (<see cref="InputPoint.IsPosition"/>),
    /// whose values are written relative to one of them at whatever it costs (½(|q|² − |p|²) of a
    /// circle through points as ½(q − p)·(q + p)). For directions it is not kept only to be more
    /// accurate than every form the macro's own statements give (u × (v − u) for the normal to u and v).
    /// </summary>
    private static void AddDifferenceForms(List<(CodeBlock Block, JoinMode Form)> candidates, List<CodeBlock> built, SideRelations relations)
    {
        if (candidates.Count == 0 || candidates[0].Block.Points.Count < 2) return;
        var errors = candidates.Select(c => AccuracyProbe.Error(c.Block, relations)).ToList();
        var anotherIsAccurate = errors.Exists(e => e <= AccuracyProbe.Threshold);
        var positions = candidates[0].Block.Points.Any(p => p.IsPosition);
        if (!errors.Exists(e => e > AccuracyProbe.Threshold)) return;
        for (var i = built.Count - 1; i >= 0; i--)
        {
            if (errors[i] is not { } e) continue;
            // An accurate form is looked at as it is, for values it computes from intermediate
            // results that are polynomials of the points alone (v1 × w2 = v1 × v2): over the
            // differences they need not wait for those results.
            var variant = e <= AccuracyProbe.Threshold
                ? Optimizer.Reduce(candidates[i].Block, differencesEverywhere: true)
                : Optimizer.Reduce(built[i], differencesEverywhere: true);
            if (candidates.Exists(c => c.Block.HasSameStatements(variant))) continue;
            if (anotherIsAccurate || positions || variant.Statistics().Cost <= candidates[i].Block.Statistics().Cost) candidates.Add((variant, candidates[i].Form));
        }
    }

    /// <summary>
    /// The caller's simplifier (side relations, assumptions), with sums cancelled against their
    /// inverses and half-angle products of sines and cosines reduced to full angles. Its answers
    /// are remembered for the whole request: the three forms and the symbolic inliner ask about the
    /// same values many times, and the caller's cache covers only its own part of the work.
    /// </summary>
    private static Func<Scalar, Scalar> EffectiveSimplifier(Func<Scalar, Scalar>? simplify)
    {
        simplify ??= s => s;
        var answers = new Dictionary<Scalar, Scalar>(); // scalars are hash-consed: a look-up is O(1)
        return s =>
        {
            if (answers.TryGetValue(s, out var known)) return known;
            var question = s;
            s = GenerationProfile.Time("caller simplify", () => simplify(s));
            for (var round = 0; round < 4 && MayCancelOrReduce(s); round++)
            {
                var reduced = GenerationProfile.Time("inverse cancellation and half angles", () => HalfAngleReduction.Apply(Rewrites.PartialInverseCancellation.Apply(InverseCancellation.CancelDeep(s))));
                if (ReferenceEquals(reduced, s)) break;
                s = simplify(reduced);
            }
            answers[question] = s;
            return s;
        };
    }

    /// <summary>
    /// Whether the scalar has an inverse, sine or cosine anywhere: the cancellations and the
    /// half-angle reduction rewrite only those, and leave everything else as it is. One walk over
    /// the atoms spares the several each of them would make.
    /// </summary>
    private static bool MayCancelOrReduce(Scalar s) => s.Atoms().Any(a => a.Kind is AtomKind.Inverse or AtomKind.Sin or AtomKind.Cos);

    /// <summary>Lowers a symbolic program (and its recorded temporaries) to an unoptimized code block.</summary>
    public static CodeBlock Build(SymbolicProgram program, IReadOnlyList<(string Name, Scalar Value)> temporaries, CodeGenerationRequest request) =>
        Build(program, temporaries, request, long.MaxValue)!;

    /// <summary>
    /// As <see cref="Build(SymbolicProgram, IReadOnlyList{ValueTuple{string, Scalar}}, CodeGenerationRequest)"/>,
    /// or null when the block's shared cost (<see cref="Rewrites.SharedCost"/>) exceeds
    /// <paramref name="sharedCostLimit"/>. Adding statements never lowers the shared cost, so the
    /// block is given up on as soon as the statements lowered so far are past the limit.
    /// </summary>
    internal static CodeBlock? Build(SymbolicProgram program, IReadOnlyList<(string Name, Scalar Value)> temporaries, CodeGenerationRequest request,
        long sharedCostLimit)
    {
        var simplify = request.Simplify ?? (s => s);
        var inputs = new HashSet<string>(request.InputText.Keys, StringComparer.Ordinal);

        // Temporaries and outputs as symbolic assignments, so the inliner can merge them.
        var assignments = temporaries.Select(t => new SymbolicInliner.Assignment(t.Name, t.Value, false)).ToList();
        var verbatim = new Dictionary<int, SymbolicVerbatim>();
        foreach (var s in program.Statements)
        {
            switch (s)
            {
                case SymbolicOutput o when request.OutputTargets.ContainsKey(o.Name):
                    assignments.Add(new SymbolicInliner.Assignment(o.Name, GenerationProfile.Time("simplify outputs", () => simplify(o.Value)), true));
                    break;
                case SymbolicVerbatim v:
                    verbatim[assignments.Count] = v; // placed before the assignment that follows it
                    break;
            }
        }
        var verbatimCount = verbatim.Count;
        if (verbatimCount == 0)
        {
            GenerationProfile.Time("symbolic inliner", () => { SymbolicInliner.Inline(assignments, s => GenerationProfile.Time("inliner simplify", () => simplify(s))); return 0; });
            GenerationProfile.Time("norm complement", () => { Rewrites.NormComplement.Apply(assignments, simplify); return 0; });
        }

        var known = new HashSet<string>(inputs, StringComparer.Ordinal);
        var spread = GenerationProfile.Time("atom spread", () => Rewrites.AtomSpread.Of(assignments.Where(a => a.IsOutput).Select(a => a.Value)));
        Expr Lower(Scalar s, string where)
        {
            var unknown = s.Variables.Where(v => !known.Contains(v)).ToArray();
            if (unknown.Length > 0)
                throw new InvalidOperationException($"{where} reads {string.Join(", ", unknown.Select(u => $"'{u}'"))}, which no input binding supplies.");
            return ScalarLowering.Lower(s, spread);
        }

        var statements = new List<CodeStatement>();
        var nextCheck = 1;
        for (var i = 0; i <= assignments.Count; i++)
        {
            // at doubling counts, so that checking costs no more than the final count
            if (sharedCostLimit < long.MaxValue && statements.Count >= nextCheck)
            {
                if (Rewrites.SharedCost.Of(new CodeBlock(statements, request.InputText, request.OutputTargets)) > sharedCostLimit) return null;
                nextCheck = 2 * statements.Count;
            }
            if (verbatim.TryGetValue(i, out var v))
                statements.Add(new VerbatimStatement(v.Parts.Select(p => p.Value is null
                    ? VerbatimPart.Literal(p.Text ?? "")
                    : VerbatimPart.Expression(Lower(simplify(p.Value), "output text"))).ToArray()));
            if (i == assignments.Count) break;
            var a = assignments[i];
            statements.Add(new AssignmentStatement(a.Name, GenerationProfile.Time("lowering", () => Lower(a.Value, a.IsOutput ? $"output {a.Name}" : $"temporary {a.Name}")), a.IsOutput));
            known.Add(a.Name);
        }
        var block = new CodeBlock(statements, request.InputText, request.OutputTargets) { EvaluatedOnce = request.EvaluatedOnce, Points = request.Points };
        return sharedCostLimit < long.MaxValue && Rewrites.SharedCost.Of(block) > sharedCostLimit ? null : block;
    }
}
