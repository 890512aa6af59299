// Test double of the Unity Test Framework 1.1.33's LogAssert and log scope (UnityEngine.TestRunner/Assertions/
// LogAssert.cs, LogScope/LogScope.cs): an error, assertion or exception logged during a test fails it unless expected;
// an expected message that never came fails it too; expectations are met in order. Here the scope is the test (the
// driver's PlayModeScope opens and checks it), where the Test Framework also checks at the end of each frame.
using System;
using System.Collections.Generic;
using System.Text.RegularExpressions;

namespace UnityEngine.TestTools
{
    public static class LogAssert
    {
        public static void Expect(LogType type, string message) => Logging.LogScope.Current.Expect(type, message, null);
        public static void Expect(LogType type, Regex message) => Logging.LogScope.Current.Expect(type, null, message);
        public static void NoUnexpectedReceived() => Logging.LogScope.Current.Check(false);

        public static bool ignoreFailingMessages
        {
            get => Logging.LogScope.Current.IgnoreFailingMessages;
            set => Logging.LogScope.Current.IgnoreFailingMessages = value;
        }
    }
}

namespace UnityEngine.TestTools.Logging
{
    internal sealed class LogScope : IDisposable
    {
        static LogScope s_current;
        readonly Queue<(LogType Type, string Message, Regex Pattern)> _expected = new Queue<(LogType, string, Regex)>();
        readonly List<string> _failing = new List<string>();

        public bool IgnoreFailingMessages { get; set; }

        public static LogScope Current => s_current ?? throw new InvalidOperationException("No log scope is available");

        public LogScope()
        {
            s_current = this;
            Application.logMessageReceived += Add;
        }

        public void Expect(LogType type, string message, Regex pattern) => _expected.Enqueue((type, message, pattern));

        void Add(string message, string stack, LogType type)
        {
            if (_expected.Count > 0)
            {
                var e = _expected.Peek();
                if (e.Type == type && (e.Pattern != null ? e.Pattern.IsMatch(message) : e.Message == message))
                {
                    _expected.Dequeue();
                    return;
                }
            }
            if ((type == LogType.Error || type == LogType.Exception || type == LogType.Assert) && !IgnoreFailingMessages)
                _failing.Add(type + ": " + message);
        }

        /// <summary>Throws on an unexpected failing message, and at the end of the scope on an expected one that never came.</summary>
        public void Check(bool endOfScope)
        {
            if (_failing.Count > 0) throw new NUnit.Framework.AssertionException("Unhandled log message: '" + _failing[0] + "'. Use UnityEngine.TestTools.LogAssert.Expect");
            if (endOfScope && _expected.Count > 0)
            {
                var e = _expected.Peek();
                throw new NUnit.Framework.AssertionException("Expected log did not appear: [" + e.Type + "] " + (e.Pattern != null ? "Regex: " + e.Pattern : e.Message));
            }
        }

        public void Dispose()
        {
            Application.logMessageReceived -= Add;
            if (ReferenceEquals(s_current, this)) s_current = null;
        }
    }
}
