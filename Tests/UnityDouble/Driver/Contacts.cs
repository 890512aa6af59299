// The tests' handle on the double (never part of the per-asmdef compile check, so package code cannot use it).
using System;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using UnityEngine;
using UnityEngine.TestTools.Logging;

namespace UnityDouble
{
    /// <summary>Contacts a test supplies (the double has no physics engine beyond spheres and boxes overlapping).</summary>
    public static class Contacts
    {
        /// <summary>From the next fixed step on, the two colliders touch (or, with false, stop touching unless they overlap).</summary>
        public static void Declare(Collider a, Collider b, bool touching) => PhysicsScene.Declare(a, b, touching);
    }

    /// <summary>What the double counts, for tests of per-frame work.</summary>
    public static class Diagnostics
    {
        /// <summary>Component searches (GetComponent, GetComponents, GetComponentInParent, GetComponentsInChildren) so far.</summary>
        public static long ComponentSearches => GameObject.Searches;
    }
}
