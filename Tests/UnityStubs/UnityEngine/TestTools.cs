// Compile-only. Transcribed from needle-mirror/com.unity.test-framework, tag 1.1.33 (the version in
// Packages/manifest.json): UnityEngine.TestRunner/NUnitExtensions/Attributes/UnityTestAttribute.cs and
// UnityEngine.TestRunner/Assertions/LogAssert.cs. The real UnityTestAttribute derives from NUnit's
// CombiningStrategyAttribute; here it is a plain method attribute, enough for [UnityTest] IEnumerator tests to compile.
using System;
using System.Text.RegularExpressions;

namespace UnityEngine.TestTools
{
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
    public class UnityTestAttribute : Attribute
    {
    }

    public static class LogAssert
    {
        public static void Expect(LogType type, string message) => throw null;
        public static void Expect(LogType type, Regex message) => throw null;
    }
}
