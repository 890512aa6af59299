// Test double of the Unity Test Framework 1.1.33's [UnityTest] (UnityEngine.TestRunner/NUnitExtensions/Attributes/
// UnityTestAttribute.cs): the same base class and interfaces, so NUnit builds the test as Unity's does (a method that
// must return IEnumerator, its return value not compared). Running it is the double's own: where the Test Framework
// runs the enumerator as a coroutine in play mode, here each `yield return null` runs one frame of the double's player
// loop (UnityEngine/Engine.cs), WaitForFixedUpdate runs frames until a fixed step has run, WaitForSeconds until that
// much game time has passed, and a yielded IEnumerator is run to its end first. For that it also implements NUnit's
// IWrapTestMethod, which the real attribute does not.
using System;
using System.Collections;
using System.Collections.Generic;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;
using NUnit.Framework.Internal.Builders;
using NUnit.Framework.Internal.Commands;

namespace UnityEngine.TestTools
{
    [AttributeUsage(AttributeTargets.Method)]
    public class UnityTestAttribute : CombiningStrategyAttribute, ISimpleTestBuilder, IImplyFixture, ITestBuilder, IApplyToTest, IWrapTestMethod
    {
        readonly NUnitTestCaseBuilder _builder = new NUnitTestCaseBuilder();

        public UnityTestAttribute() : base(new CombinatorialStrategy(), new ParameterDataSourceProvider()) { }

        TestMethod ISimpleTestBuilder.BuildFrom(IMethodInfo method, Test suite)
        {
            var parms = new TestCaseParameters { ExpectedResult = new object(), HasExpectedResult = true };
            TestMethod t = _builder.BuildTestMethod(method, suite, parms);
            parms.HasExpectedResult = false; // the enumerator is not a result to compare
            return t;
        }

        IEnumerable<TestMethod> ITestBuilder.BuildFrom(IMethodInfo method, Test suite)
        {
            if (method.GetParameters().Length == 0)
            {
                yield return ((ISimpleTestBuilder)this).BuildFrom(method, suite);
                yield break;
            }
            foreach (TestMethod t in base.BuildFrom(method, suite))
            {
                if (ParmsField.GetValue(t) is TestCaseParameters p) p.HasExpectedResult = false;
                yield return t;
            }
        }

        public new void ApplyToTest(Test test)
        {
            if (!test.Method.ReturnType.IsType(typeof(IEnumerator)))
            {
                test.RunState = RunState.NotRunnable;
                test.Properties.Set(PropertyNames.SkipReason, "Method marked with UnityTest must return IEnumerator.");
            }
            base.ApplyToTest(test);
        }

        static readonly System.Reflection.FieldInfo ParmsField =
            typeof(TestMethod).GetField("parms", System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Public);

        TestCommand ICommandWrapper.Wrap(TestCommand command) => new EnumeratorCommand((TestMethod)command.Test);

        /// <summary>Invokes the test method and runs its enumerator over the double's frames.</summary>
        sealed class EnumeratorCommand : TestCommand
        {
            const int MaxFrames = 1000000;
            readonly TestMethod _method;

            public EnumeratorCommand(TestMethod method) : base(method) => _method = method;

            public override TestResult Execute(TestExecutionContext context)
            {
                object[] args = (ParmsField.GetValue(_method) as TestCaseParameters)?.OriginalArguments ?? new object[0];
                var enumerator = (IEnumerator)_method.Method.Invoke(context.TestObject, args);
                Run(enumerator);
                context.CurrentResult.SetResult(ResultState.Success);
                return context.CurrentResult;
            }

            static void Run(IEnumerator routine)
            {
                var stack = new Stack<IEnumerator>();
                stack.Push(routine);
                int frames = 0;
                while (stack.Count > 0)
                {
                    IEnumerator top = stack.Peek();
                    if (!top.MoveNext()) { stack.Pop(); continue; }
                    switch (top.Current)
                    {
                        case IEnumerator nested: stack.Push(nested); break;
                        case WaitForFixedUpdate _:
                            double fixedBefore = Time.fixedTimeAsDouble;
                            do Frame(ref frames); while (Time.fixedTimeAsDouble == fixedBefore);
                            break;
                        case WaitForSeconds wait:
                            double until = Time.timeAsDouble + wait.Seconds;
                            do Frame(ref frames); while (Time.timeAsDouble < until - 1e-9);
                            break;
                        default: Frame(ref frames); break;
                    }
                }
            }

            static void Frame(ref int frames)
            {
                if (++frames > MaxFrames) throw new InvalidOperationException("[UnityTest] ran " + MaxFrames + " frames without finishing.");
                Engine.Frame(Engine.DefaultFrameTime);
            }
        }
    }
}
