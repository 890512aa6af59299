using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The grab transformers' shared bookkeeping (<see cref="GrabbingHands{T}"/>) and frame time (<see cref="FrameClock"/>).</summary>
    public sealed class GrabbingHandsTests
    {
        sealed class Interactor
        {
            public readonly string Name;
            public Interactor(string name) => Name = name;
        }

        static readonly Interactor A = new Interactor("a"), B = new Interactor("b"), C = new Interactor("c");

        [Test]
        public void HandsKeepTheOrderTheyJoinedInAndALeaverClosesTheGap()
        {
            var hands = new GrabbingHands<Interactor>(capacity: 1);
            Assert.That(hands.Add(7, A), Is.True);
            Assert.That(hands.Add(3, B), Is.True, "grows past its capacity");
            Assert.That(hands.Add(9, C), Is.True);
            Assert.That(hands.Add(3, A), Is.False, "an id already here");
            Assert.That(hands.Remove(7), Is.True);
            Assert.That(hands.Remove(7), Is.False);
            Assert.That(hands.Count, Is.EqualTo(2));
            Assert.That(new[] { hands.IdAt(0), hands.IdAt(1) }, Is.EqualTo(new[] { 3, 9 }));
            Assert.That(hands.SourceAt(0), Is.SameAs(B));
            Assert.That(hands.IndexOf(9), Is.EqualTo(1));
            Assert.That(hands.IndexOfSource(A), Is.EqualTo(-1));
        }

        [Test]
        public void NumberedHandsNeverReuseAnIdInUseAndASourceKeepsItsId()
        {
            var hands = new GrabbingHands<Interactor>();
            hands.Add(1, A);
            int b = hands.Add(B), c = hands.Add(C);
            Assert.That(new[] { 1, b, c }, Is.Unique);
            Assert.That(hands.Add(B), Is.EqualTo(b), "B is here already");
            hands.Remove(b);
            int again = hands.Add(B);
            Assert.That(again, Is.Not.EqualTo(1).And.Not.EqualTo(c), "a new id, not one in use");
            Assert.That(hands.Count, Is.EqualTo(3));
        }

        [Test]
        public void ResyncingAgainstTheGrabSystemsListGivesEachLeaverOnceAndKeepsTheStayers()
        {
            var hands = new GrabbingHands<Interactor>();
            int a = hands.Add(A), b = hands.Add(B), c = hands.Add(C);
            var current = new List<Interactor> { C, A };
            var gone = new List<int>();
            while (hands.TakeGone(current, out int id)) gone.Add(id);
            Assert.That(gone, Is.EqualTo(new[] { b }));
            Assert.That(hands.IndexOfSource(A), Is.EqualTo(0), "the stayers keep their join order");
            Assert.That(hands.IdAt(1), Is.EqualTo(c));
            while (hands.TakeGone(new List<Interactor>(), out int id)) gone.Add(id);
            Assert.That(gone, Is.EqualTo(new[] { b, a, c }));
            Assert.That(hands.Count, Is.Zero);
            Assert.That(hands.TakeGone(null, out _), Is.False);
        }

        [Test]
        public void TheCancelSnapshotIsACopyThatOutlivesTheLeaving()
        {
            var hands = new GrabbingHands<Interactor>();
            hands.Add(4, A);
            hands.Add(5, B);
            int[] buffer = new int[1];
            int n = hands.CopyIds(ref buffer);
            hands.Clear();
            Assert.That(n, Is.EqualTo(2));
            Assert.That(new[] { buffer[0], buffer[1] }, Is.EqualTo(new[] { 4, 5 }));
            Assert.That(hands.Count, Is.Zero);
        }

        [Test]
        public void LookupsResyncsAndSnapshotsAllocateNothing()
        {
            var hands = new GrabbingHands<Interactor>();
            var current = new List<Interactor> { A, B };
            IReadOnlyList<Interactor> view = current;
            int[] buffer = new int[4];
            Allocation.AssertNone(count =>
            {
                for (int i = 0; i < count; i++)
                {
                    hands.Add(i % 2 == 0 ? A : B); // present after the first: keeps its id
                    hands.TakeGone(view, out _);
                    hands.CopyIds(ref buffer);
                    hands.IndexOfSource(B);
                }
            }, "resyncs");
        }

        [Test]
        public void TheClockGivesTheTimeSinceTheLastCallAndZeroForASecondCallInAFrame()
        {
            var clock = new FrameClock();
            Assert.That(clock.Delta(5.0), Is.Zero, "before a start");
            clock.Start(10.0);
            Assert.That(clock.Delta(10.0), Is.Zero, "the grab's own frame");
            Assert.That(clock.Delta(10.0 + 1.0 / 90), Is.EqualTo(1f / 90).Within(1e-6f));
            Assert.That(clock.Delta(10.0 + 1.0 / 90), Is.Zero, "called twice in a frame");
            Assert.That(clock.Delta(9.0), Is.Zero, "time never runs backwards here");
            Assert.That(clock.Delta(9.5), Is.EqualTo(0.5f).Within(1e-6f), "and goes on from where it was given");
            Assert.That(clock.Delta(double.NaN), Is.Zero);
            Assert.That(float.IsFinite(clock.Delta(11.0)), Is.True);
        }

        [Test]
        public void ANonPositiveCapacityIsRefusedNamingIt()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new GrabbingHands<Interactor>(0));
            Assert.That(e.ParamName, Is.EqualTo("capacity"));
            Assert.That(e.Message, Does.Contain("capacity must be at least 1"));
        }

        [Test]
        public void AFullSetLooksUpLetsGoAndClearsWithoutOverrunning()
        {
            var hands = new GrabbingHands<Interactor>(capacity: 2);
            hands.Add(1, A);
            hands.Add(2, B);
            Assert.That(hands.IndexOfSource(C), Is.EqualTo(-1));
            Assert.That(hands.IndexOfSource(null), Is.EqualTo(-1), "no hand has a null source");
            Assert.That(hands.Remove(1), Is.True);
            Assert.That(hands.IndexOfSource(null), Is.EqualTo(-1), "the slot a leaver freed is not a hand");
            Assert.That(hands.IdAt(0), Is.EqualTo(2));
            hands.Add(3, C);
            hands.Clear();
            Assert.That(hands.Count, Is.Zero);
            Assert.That(hands.IndexOfSource(B), Is.EqualTo(-1));
        }

        [Test]
        public void AnIdAlreadyHereIsRefusedWhicheverHandHasIt()
        {
            var hands = new GrabbingHands<Interactor>();
            hands.Add(7, A);
            Assert.That(hands.Add(7, B), Is.False, "the first hand's id");
            Assert.That(hands.Count, Is.EqualTo(1));
            Assert.That(hands.SourceAt(0), Is.SameAs(A));
        }

        /// <summary>
        /// A hand that lets go and a new one that grabs in the same frame must not share an id: the hold would take the new
        /// hand's pose for the old hand's motion (a jump), not for a join. So numbered ids only go up, past every id given
        /// or taken so far, until the numbering passes int.MaxValue (300 seeds of random joins, caller ids and leaves).
        /// </summary>
        [Test]
        public void AnIdThatLeftIsNeverNumberedAgainBeforeTheNumberingWraps()
        {
            for (int seed = 1; seed <= 300; seed++)
            {
                var random = new Random(seed);
                var hands = new GrabbingHands<Interactor>(capacity: 2);
                int highest = 0; // the highest id ever here
                for (int op = 0; op < 60; op++)
                {
                    int roll = random.Next(3);
                    if (roll == 0)
                    {
                        int id = hands.Add(new Interactor("n"));
                        Assert.That(id, Is.GreaterThan(highest), "seed " + seed + ", op " + op + ": a new id above every id so far");
                        highest = id;
                    }
                    else if (roll == 1)
                    {
                        int id = random.Next(1, 40); // a caller's id (the Interaction SDK's pointer ids), maybe one that left
                        if (hands.Add(id, new Interactor("c"))) highest = Math.Max(highest, id);
                    }
                    else if (hands.Count > 0) hands.Remove(hands.IdAt(random.Next(hands.Count)));
                }
            }
        }

        /// <summary>Ids up to int.MaxValue (the Interaction SDK's pointer ids are anything) make the numbering wrap; it still never gives an id in use.</summary>
        [Test]
        public void NumberedIdsStayFreeAfterTheNumberingWraps()
        {
            var hands = new GrabbingHands<Interactor>();
            hands.Add(1, B);
            hands.Add(2, C);
            hands.Add(int.MaxValue, A);
            var d = new Interactor("d");
            int id = hands.Add(d);
            Assert.That(new[] { 1, 2, int.MaxValue, id }, Is.Unique);
            Assert.That(id, Is.EqualTo(3), "wrapped to 1, the first id not in use from there");
            Assert.That(hands.Count, Is.EqualTo(4));
            Assert.That(hands.SourceAt(hands.IndexOf(id)), Is.SameAs(d));
        }

        [Test]
        public void TheCancelSnapshotKeepsABufferThatFitsAndGrowsOneThatDoesNot()
        {
            var hands = new GrabbingHands<Interactor>();
            for (int i = 1; i <= 6; i++) hands.Add(10 + i, new Interactor("h" + i));
            int[] exact = new int[6], kept = exact;
            Assert.That(hands.CopyIds(ref exact), Is.EqualTo(6));
            Assert.That(exact, Is.SameAs(kept), "a buffer of exactly the hands' count is used as it is");
            int[] none = null;
            Assert.That(hands.CopyIds(ref none), Is.EqualTo(6));
            Assert.That(new[] { none[0], none[5] }, Is.EqualTo(new[] { 11, 16 }));
        }

        [Test]
        public void AClockNeverStartedStartsAtItsFirstCall()
        {
            var clock = new FrameClock();
            Assert.That(clock.Delta(5.0), Is.Zero);
            Assert.That(clock.Delta(5.5), Is.EqualTo(0.5f).Within(1e-6f), "the time since that first call");
        }
    }
}
