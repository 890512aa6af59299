using NUnit.Framework;

namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>The rules the compile check applies, each against cases from Unity's manual.</summary>
public class CompilationRulesTests
{
    [TestCase("49.0.0", "68.0.2", true)]
    [TestCase("69.0.0", "68.0.2", false)]
    [TestCase("[68.0.2]", "68.0.2", true)]
    [TestCase("[68.0.1]", "68.0.2", false)]
    [TestCase("(68.0.2,)", "68.0.2", false)]
    [TestCase("(68.0.1,)", "68.0.2", true)]
    [TestCase("(,68.0.2]", "68.0.2", true)]
    [TestCase("(,68.0.2)", "68.0.2", false)]
    [TestCase("[1.0,2.0)", "1.5.0", true)]
    [TestCase("[1.0,2.0)", "2.0.0", false)]
    [TestCase("(1.0,2.0]", "1.0.0", false)]
    [TestCase("1.5.0", "1.5.0-pre.4", false)]
    [TestCase("2022.3", "2022.3.50f1", true)]
    [TestCase("[2022.3.50f1]", "2022.3.50f1", true)]
    [TestCase("2022.3.51f1", "2022.3.50f1", false)]
    public void VersionExpressions(string expression, string version, bool matches) =>
        Assert.That(VersionExpression.Matches(expression, version), Is.EqualTo(matches));

    [TestCase("[1.0,)")]
    [TestCase("(1.0)")]
    [TestCase("1.0]")]
    public void ExpressionsUnityRefuses(string expression) =>
        Assert.That(() => VersionExpression.Matches(expression, "1.0.0"), Throws.TypeOf<FormatException>());

    [TestCase(new[] { "A" }, new[] { "A" }, true)]
    [TestCase(new[] { "A" }, new[] { "B" }, false)]
    [TestCase(new[] { "A" }, new[] { "!A" }, false)]
    [TestCase(new[] { "A" }, new[] { "!B" }, true)]
    [TestCase(new[] { "A" }, new[] { "B || A" }, true)]
    [TestCase(new[] { "A" }, new[] { "B || !C" }, true)]
    [TestCase(new[] { "A" }, new[] { "A", "B" }, false)]
    public void DefineConstraintsHoldAsUnityReadsThem(string[] defines, string[] constraints, bool hold) =>
        Assert.That(DefineConstraints.Hold(defines, constraints), Is.EqualTo(hold));

    [Test]
    public void TheEditorOnAndroidHasTheEditorsSymbolsAndThePlayerNot()
    {
        var editor = ScriptingSymbols.For(UnityTarget.EditorAndroid, "2022.3.50f1", false);
        var player = ScriptingSymbols.For(UnityTarget.PlayerAndroid, "2022.3.50f1", false);
        Assert.That(editor, Is.SupersetOf(new[] { "UNITY_EDITOR", "UNITY_ANDROID", "UNITY_INCLUDE_TESTS", "UNITY_2022_3_OR_NEWER", "UNITY_5_3_OR_NEWER", "UNITY_2022_3_50", "NET_STANDARD_2_1" }));
        Assert.That(editor, Does.Not.Contain("UNITY_2023_1_OR_NEWER"));
        Assert.That(player, Does.Contain("UNITY_ANDROID").And.Contain("ENABLE_IL2CPP"));
        Assert.That(player, Does.Not.Contain("UNITY_EDITOR").And.Not.Contain("UNITY_INCLUDE_TESTS"));
    }
}
