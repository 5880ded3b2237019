using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// Recursive-descent reader of conventional scalar syntax: numbers (exact, with decimals and
/// exponents), identifiers of letters, digits, '_' and '.', <c>+ - * / ^</c>, unary signs,
/// parentheses, the functions sin cos tan sqrt exp log atan2 abs pow, and the constant pi.
/// Precedence: + - &lt; * / &lt; unary sign &lt; ^ (right associative, its exponent may be signed).
/// </summary>
internal sealed class ScalarParser
{
    // Integer powers are expanded, so an absurd exponent would only exhaust memory.
    private const int MaxIntegerExponent = 4096;

    // Nesting deeper than this is refused rather than risking the stack.
    private const int MaxDepth = 200;

    private readonly string _text;
    private readonly List<Scalar>? _names;
    private int _position;
    private int _depth;

    private ScalarParser(string text, List<Scalar>? names = null)
    {
        _text = text;
        _names = names;
    }

    public static Scalar Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var parser = new ScalarParser(text);
        parser.SkipSpace();
        if (parser.AtEnd) throw parser.Error("expected an expression but the text is empty", parser._position);
        var result = parser.ParseSum();
        parser.SkipSpace();
        if (!parser.AtEnd) throw parser.Error($"unexpected '{text[parser._position]}'", parser._position);
        return result;
    }

    /// <summary>
    /// Reads the shared form of <see cref="ScalarPrinter.FormatShared"/>: definitions
    /// <c>$k = expression;</c> numbered from 0, each reading only earlier names, then the expression.
    /// </summary>
    public static Scalar ParseShared(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var names = new List<Scalar>();
        var parts = text.Split(';');
        for (var i = 0; i < parts.Length - 1; i++)
        {
            var part = parts[i].AsSpan().Trim();
            var prefix = $"${names.Count} =";
            if (!part.StartsWith(prefix, StringComparison.Ordinal))
                throw new ScalarSyntaxException($"expected the definition '{prefix} ...'", 1, parts[i]);
            names.Add(new ScalarParser(part[prefix.Length..].ToString(), names).ParseWhole());
        }
        return new ScalarParser(parts[^1], names).ParseWhole();
    }

    private Scalar ParseWhole()
    {
        SkipSpace();
        if (AtEnd) throw Error("expected an expression but the text is empty", _position);
        var result = ParseSum();
        SkipSpace();
        if (!AtEnd) throw Error($"unexpected '{_text[_position]}'", _position);
        return result;
    }

    public static bool IsIdentifier(string name)
    {
        if (string.IsNullOrEmpty(name) || !IsIdentifierStart(name[0])) return false;
        foreach (var c in name)
            if (!IsIdentifierPart(c)) return false;
        return true;
    }

    private static bool IsIdentifierStart(char c) => char.IsAsciiLetter(c) || c == '_';
    private static bool IsIdentifierPart(char c) => char.IsAsciiLetterOrDigit(c) || c == '_' || c == '.';

    private bool AtEnd => _position >= _text.Length;

    private char Current => AtEnd ? '\0' : _text[_position];

    private ScalarSyntaxException Error(string reason, int position) => new(reason, position + 1, _text);

    private void SkipSpace()
    {
        while (!AtEnd && char.IsWhiteSpace(_text[_position])) _position++;
    }

    private bool Accept(char c)
    {
        SkipSpace();
        if (Current != c) return false;
        _position++;
        return true;
    }

    private void Expect(char c, string context)
    {
        SkipSpace();
        if (Current == c)
        {
            _position++;
            return;
        }
        var found = AtEnd ? "the end of the text" : $"'{Current}'";
        throw Error($"expected '{c}' {context} but found {found}", _position);
    }

    /// <summary>
    /// A sum, its terms gathered and combined once: adding them one by one costs quadratic time,
    /// and a long sum (a cached simplification) would meet the limit on sums built that way.
    /// </summary>
    private Scalar ParseSum()
    {
        var first = ParseProduct();
        List<Term>? terms = null;
        while (true)
        {
            var negate = false;
            if (Accept('+')) { }
            else if (Accept('-')) negate = true;
            else return terms is null ? first : Scalar.FromTerms(terms);
            terms ??= [.. first.Terms];
            foreach (var t in ParseProduct().Terms) terms.Add(negate ? t with { Coefficient = -t.Coefficient } : t);
        }
    }

    private Scalar ParseProduct()
    {
        var result = ParseUnary();
        while (true)
        {
            if (Accept('*')) result *= ParseUnary();
            else if (Accept('/'))
            {
                SkipSpace();
                var at = _position;
                var divisor = ParseUnary();
                if (divisor.TryGetConstant(out var c) && c.IsZero) throw Error("division by zero", at);
                result /= divisor;
            }
            else return result;
        }
    }

    private Scalar ParseUnary()
    {
        SkipSpace();
        if (++_depth > MaxDepth) throw Error($"the expression is nested more than {MaxDepth} levels deep", _position);
        try
        {
            if (Accept('-')) return -ParseUnary();
            if (Accept('+')) return ParseUnary();
            return ParsePower();
        }
        finally
        {
            _depth--;
        }
    }

    private Scalar ParsePower()
    {
        var start = _position;
        var baseValue = ParsePrimary();
        if (!Accept('^')) return baseValue;
        SkipSpace();
        var at = _position;
        var exponent = ParseUnary();
        if (baseValue.TryGetConstant(out var b) && b.IsZero && exponent.TryGetConstant(out var e) && e.Sign < 0)
            throw Error("zero raised to a negative power", start);
        if (exponent.TryGetConstant(out var power) && power.IsInteger && BigInteger.Abs(power.Numerator) > MaxIntegerExponent)
            throw Error($"the exponent is larger than {MaxIntegerExponent} in size", at);
        try
        {
            return Scalar.Pow(baseValue, exponent);
        }
        catch (OverflowException)
        {
            throw Error("the exponent is too large", at);
        }
        catch (DivideByZeroException)
        {
            throw Error("zero raised to a negative power", start);
        }
    }

    private Scalar ParsePrimary()
    {
        SkipSpace();
        var start = _position;
        if (AtEnd) throw Error("expected a number, a name or '(' but found the end of the text", start);
        var c = Current;
        if (char.IsAsciiDigit(c) || (c == '.' && _position + 1 < _text.Length && char.IsAsciiDigit(_text[_position + 1])))
            return ParseNumber();
        if (IsIdentifierStart(c)) return ParseName();
        if (c == '$' && _names is not null)
        {
            _position++;
            var digits = _position;
            while (char.IsAsciiDigit(Current)) _position++;
            if (!int.TryParse(_text.AsSpan(digits, _position - digits), out var index) || index >= _names.Count)
                throw Error("'$' must be followed by the number of an earlier definition", start);
            return _names[index];
        }
        if (c == '(')
        {
            _position++;
            var inner = ParseSum();
            Expect(')', "to close the parenthesis");
            return inner;
        }
        throw Error($"expected a number, a name or '(' but found '{c}'", start);
    }

    private Scalar ParseNumber()
    {
        var start = _position;
        while (char.IsAsciiDigit(Current)) _position++;
        if (Current == '.')
        {
            _position++;
            while (char.IsAsciiDigit(Current)) _position++;
        }
        if (Current is 'e' or 'E')
        {
            var save = _position;
            _position++;
            if (Current is '+' or '-') _position++;
            if (!char.IsAsciiDigit(Current)) throw Error("expected digits in the exponent of the number", save);
            var digits = _position;
            while (char.IsAsciiDigit(Current)) _position++;
            if (_position - digits > 4) throw Error("the exponent of the number is too large", save);
        }
        if (IsIdentifierStart(Current)) throw Error($"unexpected '{Current}' after a number (write '*' for a product)", _position);
        var token = _text[start.._position];
        if (!Rational.TryParse(token, out var value)) throw Error($"'{token}' is not a valid number", start);
        return Scalar.Constant(value);
    }

    private Scalar ParseName()
    {
        var start = _position;
        while (!AtEnd && IsIdentifierPart(Current)) _position++;
        var name = _text[start.._position];
        if (name.EndsWith('.')) throw Error($"a name cannot end with '.': '{name}'", _position - 1);
        SkipSpace();
        if (Current != '(')
            return name == "pi" ? Scalar.Pi : Scalar.Variable(name);

        var arity = name switch
        {
            "sin" or "cos" or "tan" or "sqrt" or "exp" or "log" or "abs" or "sinh" or "cosh" => 1,
            "atan2" or "pow" => 2,
            _ => throw Error($"unknown function '{name}' (known: sin, cos, tan, sqrt, exp, log, atan2, abs, pow, sinh, cosh)", start),
        };
        _position++;
        var arguments = new List<Scalar> { ParseSum() };
        while (Accept(',')) arguments.Add(ParseSum());
        SkipSpace();
        if (arguments.Count != arity)
            throw Error($"'{name}' takes {arity} argument{(arity == 1 ? "" : "s")} but was given {arguments.Count}", start);
        Expect(')', $"to close the arguments of '{name}'");
        try
        {
            return ApplyFunction(name, arguments);
        }
        catch (Exception e) when (e is DivideByZeroException or OverflowException)
        {
            throw Error($"'{name}' is undefined for these arguments: {e.Message}", start);
        }
    }

    private static Scalar ApplyFunction(string name, List<Scalar> arguments)
    {
        return name switch
        {
            "sin" => Scalar.Sin(arguments[0]),
            "cos" => Scalar.Cos(arguments[0]),
            "tan" => Scalar.Tan(arguments[0]),
            "sqrt" => Scalar.Sqrt(arguments[0]),
            "exp" => Scalar.Exp(arguments[0]),
            "log" => Scalar.Log(arguments[0]),
            "abs" => Scalar.Abs(arguments[0]),
            // Printed text says sinh only for the atom (Scalar.Sinh prints as exponentials).
            "sinh" => Scalar.HyperbolicSine(arguments[0]),
            "cosh" => Scalar.HyperbolicCosine(arguments[0]),
            "atan2" => Scalar.Atan2(arguments[0], arguments[1]),
            _ => Scalar.Pow(arguments[0], arguments[1]),
        };
    }
}
