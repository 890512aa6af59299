using System.Globalization;
using System.Threading;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The Unity layer's double-precision vector: its arithmetic and its culture-independent text.</summary>
    public sealed class Vector3dTests
    {
        static readonly Vector3d A = new Vector3d(1, 2, 3);

        [Test]
        public void ArithmeticActsOnEveryCoordinate()
        {
            Assert.That(A * 2, Is.EqualTo(new Vector3d(2, 4, 6)));
            Assert.That(new Vector3d(2, 4, 6) / 2, Is.EqualTo(A));
            Assert.That(-A, Is.EqualTo(new Vector3d(-1, -2, -3)));
            Assert.That(A + -A, Is.EqualTo(Vector3d.Zero));
        }

        [Test]
        public void LengthsAndDistancesArePythagorean()
        {
            Assert.That(new Vector3d(0, 0, 2).SqrLength, Is.EqualTo(4));
            Assert.That(A.SqrLength, Is.EqualTo(A.Length * A.Length).Within(1e-12));
            Assert.That(Vector3d.Distance(new Vector3d(1, 1, 7), new Vector3d(4, 5, 7)), Is.EqualTo(5), "a 3-4-5 triangle");
            Assert.That(Vector3d.Distance(A, A), Is.EqualTo(0));
        }

        /// <summary>The text shown in logs and test failures: coordinates to a tenth of a millimetre, a point as decimal mark whatever the culture.</summary>
        [Test]
        public void TheTextListsTheCoordinatesToATenthOfAMillimetreInAnyCulture()
        {
            CultureInfo saved = Thread.CurrentThread.CurrentCulture;
            try
            {
                var comma = (CultureInfo)CultureInfo.InvariantCulture.Clone();
                comma.NumberFormat.NumberDecimalSeparator = ",";
                Thread.CurrentThread.CurrentCulture = comma;
                Assert.That(new Vector3d(1.23456, -2.00001, 0.000012).ToString(), Is.EqualTo("(1.2346, -2, 0)"));
            }
            finally
            {
                Thread.CurrentThread.CurrentCulture = saved;
            }
        }
    }
}
