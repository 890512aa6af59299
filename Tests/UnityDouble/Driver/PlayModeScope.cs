// The tests' handle on the double (never part of the per-asmdef compile check, so package code cannot use it).
using System;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using UnityEngine;
using UnityEngine.TestTools.Logging;

namespace UnityDouble
{
    /// <summary>
    /// Put on a test assembly (<c>[assembly: PlayModeScope]</c>): each test starts in an empty scene with the clock at
    /// zero, inside a log scope (an unexpected error, assertion or exception logged fails it, and so does an expected
    /// message that never came, as in Unity's Test Framework), and its objects are destroyed after it. Unity keeps one
    /// scene for a whole play-mode run; here no test can disturb another through objects it left behind.
    /// </summary>
    [AttributeUsage(AttributeTargets.Assembly | AttributeTargets.Class | AttributeTargets.Method)]
    public sealed class PlayModeScopeAttribute : Attribute, ITestAction
    {
        [ThreadStatic] static LogScope s_scope;

        public ActionTargets Targets => ActionTargets.Test;

        public void BeforeTest(ITest test)
        {
            Engine.Reset();
            UnityEditor.EditorState.Reset();
            OVRProjectConfig.ResetForTests();
            Application.IsBatchModeState = false;
            s_scope = new LogScope();
        }

        public void AfterTest(ITest test)
        {
            LogScope scope = s_scope;
            s_scope = null;
            try
            {
                if (TestContext.CurrentContext.Result.Outcome.Status != TestStatus.Failed) scope?.Check(true);
            }
            finally
            {
                scope?.Dispose();
                Engine.Reset();
            }
        }
    }
}
