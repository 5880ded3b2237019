namespace GMac.Core.CodeGeneration;

/// <summary>
/// One form of a macro (split by operation, by statement, or joined) is too large to evaluate
/// symbolically. The generator drops that form and keeps the others; when every form is too
/// large it rethrows <see cref="Exception.InnerException"/>, the evaluator's own report.
/// </summary>
public sealed class FormTooLargeException(Exception inner) : Exception(inner.Message, inner);
