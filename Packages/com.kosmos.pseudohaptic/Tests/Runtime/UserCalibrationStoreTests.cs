using System.IO;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    public sealed class UserCalibrationStoreTests
    {
        string _folder;

        [SetUp]
        public void UseTemporaryStore()
        {
            _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-store-" + System.Guid.NewGuid().ToString("N"));
            UserCalibrationStore.SetRootForTests(_folder);
        }

        [TearDown]
        public void RemoveTemporaryStore()
        {
            UserCalibrationStore.SetRootForTests(null);
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        static UserCalibration Calibration(string user, double speed) =>
            UserCalibration.From(user, new CalibrationResult(true, speed, 5, 5, 0.05, null));

        [Test]
        public void WhatIsSavedIsLoadedAndNoTemporaryFileStays()
        {
            string path = UserCalibrationStore.Save(Calibration("ana", 0.62));
            UserCalibrationStore.Save(Calibration("ana", 0.71)); // replaces the first
            Assert.That(UserCalibrationStore.TryLoad("ana", out UserCalibration c, out string error), Is.True, error);
            Assert.That(c.standardSpeed, Is.EqualTo(0.71));
            Assert.That(c.liftsUsed, Is.EqualTo(5));
            Assert.That(File.Exists(path + ".tmp"), Is.False);
        }

        [Test]
        public void AUserWithoutCalibrationGetsTheDefaultSpeed()
        {
            UserCalibrationStore.CurrentUserId = "nobody";
            Assert.That(UserCalibrationStore.TryLoad("nobody", out _, out string error), Is.False);
            Assert.That(error, Is.Null);
            Assert.That(UserCalibrationStore.StandardSpeedOrDefault, Is.EqualTo(WeightSolver.DefaultStandardSpeed));
            UserCalibrationStore.CurrentUserId = null;
        }

        [Test]
        public void ACorruptOrOutOfRangeFileIsRefusedWithTheReason()
        {
            Directory.CreateDirectory(_folder);
            File.WriteAllText(UserCalibrationStore.PathFor("broken"), "{ not json");
            Assert.That(UserCalibrationStore.TryLoad("broken", out _, out string error), Is.False);
            Assert.That(error, Is.Not.Null);

            File.WriteAllText(UserCalibrationStore.PathFor("fast"), "{\"format\":1,\"standardSpeed\":50.0}");
            Assert.That(UserCalibrationStore.TryLoad("fast", out _, out error), Is.False);
            Assert.That(error, Does.Contain("standardSpeed"));
        }

        [Test]
        public void AFormatOneFileIsStillReadWithTheDefaultCueStrength()
        {
            Directory.CreateDirectory(_folder);
            File.WriteAllText(UserCalibrationStore.PathFor("old"), "{\"format\":1,\"userId\":\"old\",\"standardSpeed\":0.6,\"liftsUsed\":5,\"liftsOffered\":5}");
            Assert.That(UserCalibrationStore.TryLoad("old", out UserCalibration c, out string error), Is.True, error);
            Assert.That(c.standardSpeed, Is.EqualTo(0.6));
            Assert.That(c.cueStrength, Is.EqualTo(1.0));
            Assert.That(c.format, Is.EqualTo(UserCalibration.CurrentFormat), "brought to the current format when read");

            File.WriteAllText(UserCalibrationStore.PathFor("future"), "{\"format\":3,\"standardSpeed\":0.6}");
            Assert.That(UserCalibrationStore.TryLoad("future", out _, out error), Is.False);
            Assert.That(error, Does.Contain("format 3"));
        }

        [Test]
        public void TheCueStrengthIsStoredBesideTheStandardSpeedWithinItsBounds()
        {
            UserCalibrationStore.Save(Calibration("bo", 0.58));
            UserCalibrationStore.SaveCueStrength("bo", 0.7, 0.12);
            Assert.That(UserCalibrationStore.TryLoad("bo", out UserCalibration c, out string error), Is.True, error);
            Assert.That((c.standardSpeed, c.cueStrength, c.cueWeber), Is.EqualTo((0.58, 0.7, 0.12)));
            Assert.Throws<System.ArgumentException>(() => UserCalibrationStore.SaveCueStrength("bo", 5, 0.9));
            Assert.That(UserCalibrationStore.TryLoad("bo", out c, out _), Is.True);
            Assert.That(c.cueStrength, Is.EqualTo(0.7), "a refused strength leaves the file as it was");
            File.WriteAllText(UserCalibrationStore.PathFor("wild"), "{\"format\":2,\"standardSpeed\":0.6,\"cueStrength\":0}");
            Assert.That(UserCalibrationStore.TryLoad("wild", out _, out error), Is.False);
            Assert.That(error, Does.Contain("cueStrength"));
        }

        /// <summary>
        /// "P 1" and "P_1" (or "P1" and "p1" on a Quest's storage, which ignores case) had one file: the second user's
        /// calibration replaced the first's, and each was then given the other's standard speed and cue strength.
        /// </summary>
        [Test]
        public void TwoUsersWhoseIdsMakeOneFileNameKeepTheirOwnCalibrations()
        {
            UserCalibrationStore.Save(Calibration("P_1", 0.62));
            UserCalibrationStore.Save(Calibration("P 1", 0.41));
            UserCalibrationStore.SaveCueStrength("P.1", 0.8, 0.1);
            Assert.That(UserCalibrationStore.TryLoad("P_1", out UserCalibration a, out string error), Is.True, error);
            Assert.That(UserCalibrationStore.TryLoad("P 1", out UserCalibration b, out error), Is.True, error);
            Assert.That(UserCalibrationStore.TryLoad("P.1", out UserCalibration c, out error), Is.True, error);
            Assert.That((a.userId, a.standardSpeed, a.cueStrength), Is.EqualTo(("P_1", 0.62, 1.0)));
            Assert.That((b.userId, b.standardSpeed, b.cueStrength), Is.EqualTo(("P 1", 0.41, 1.0)));
            Assert.That((c.userId, c.standardSpeed, c.cueStrength), Is.EqualTo(("P.1", WeightSolver.DefaultStandardSpeed, 0.8)));
            Assert.That(UserCalibrationStore.PathFor("P 1"), Does.EndWith("user-P_1-2.json"));
            Assert.That(UserCalibrationStore.TryLoad("P/1", out _, out error), Is.False, "P/1 makes the same name; the three files are others'");
            Assert.That(error, Is.Null);
            Assert.That(UserCalibrationStore.PathFor("P/1"), Does.EndWith("user-P_1-4.json"));

            // The current user is told of their own calibration only, not of another's with the same file name.
            UserCalibrationStore.CurrentUserId = "P 1";
            int changes = 0;
            void Count() => changes++;
            UserCalibrationStore.Changed += Count;
            UserCalibrationStore.Save(Calibration("P_1", 0.7));
            UserCalibrationStore.Changed -= Count;
            UserCalibrationStore.CurrentUserId = null;
            Assert.That(changes, Is.EqualTo(0));
        }

        [Test]
        public void AFileThatRecordsNoUserIsStillItsNamesFirstUsers()
        {
            // Written by hand or by a version that did not record the user: found as before.
            Directory.CreateDirectory(_folder);
            File.WriteAllText(Path.Combine(_folder, "user-P_1.json"), "{\"format\":2,\"standardSpeed\":0.6}");
            Assert.That(UserCalibrationStore.TryLoad("P 1", out UserCalibration c, out string error), Is.True, error);
            Assert.That(c.standardSpeed, Is.EqualTo(0.6));
        }

        [Test]
        public void SavingTheCurrentUserTellsTheComponents()
        {
            int changes = 0;
            void Count() => changes++;
            UserCalibrationStore.Changed += Count;
            UserCalibrationStore.Save(Calibration(UserCalibrationStore.CurrentUserId, 0.55));
            UserCalibrationStore.Changed -= Count;
            Assert.That(changes, Is.EqualTo(1));
            Assert.That(UserCalibrationStore.StandardSpeedOrDefault, Is.EqualTo(0.55));
        }
    }
}
