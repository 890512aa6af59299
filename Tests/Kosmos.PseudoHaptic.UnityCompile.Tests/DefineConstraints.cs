namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>
/// An asmdef's defineConstraints, as Unity 2022.3 evaluates them (UnityCsReference
/// Editor/Mono/Scripting/ScriptCompilation/DefineConstraintsHelper.cs): every constraint must hold; a constraint is
/// symbols joined by <c>||</c>, each maybe negated by <c>!</c>, and holds when one of its plain symbols is defined or
/// one of its negated symbols is not.
/// </summary>
public static class DefineConstraints
{
    public static bool Hold(IReadOnlyCollection<string> defines, IEnumerable<string> constraints) =>
        constraints.All(c => Holds(defines, c));

    static bool Holds(IReadOnlyCollection<string> defines, string constraint)
    {
        var terms = constraint.Split("||").Select(t => t.Trim(' ', '\t')).ToList();
        if (terms.Any(t => t.Length == 0 || t == "!")) throw new FormatException("invalid define constraint '" + constraint + "'");
        return terms.Any(t => t.StartsWith('!') ? !defines.Contains(t[1..]) : defines.Contains(t));
    }
}
