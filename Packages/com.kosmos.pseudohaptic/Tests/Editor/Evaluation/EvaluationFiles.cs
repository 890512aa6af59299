using System.IO;
using System.Runtime.CompilerServices;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Finds files for the evaluation tests from this source file's own location, which the compiler records
    /// (absolute under dotnet; relative to the project, Unity's working folder, under Unity).
    /// </summary>
    internal static class EvaluationFiles
    {
        /// <summary>The package's questionnaire definitions; the test is ignored if the package cannot be located.</summary>
        public static string QuestionnaireDirectory()
        {
            for (var dir = ThisDirectory(); dir != null; dir = dir.Parent)
            {
                string candidate = Path.Combine(dir.FullName, "Runtime", "Evaluation", "Questionnaires");
                if (File.Exists(Path.Combine(dir.FullName, "package.json")) && Directory.Exists(candidate)) return candidate;
            }
            Assert.Ignore("The package folder (Runtime/Evaluation/Questionnaires) could not be located from " + SourcePath());
            return null;
        }

        public static QuestionnaireCatalog PackageCatalog() => QuestionnaireJson.LoadDirectory(QuestionnaireDirectory());

        /// <summary>
        /// A file under the shared folder that sits beside the repository (../shared/ from its root), found by
        /// walking up from this file and from the test run's folder; the test is ignored when it is absent.
        /// </summary>
        public static string SharedFile(string relativePath)
        {
            foreach (var start in new[] { ThisDirectory(), new DirectoryInfo(TestContext.CurrentContext.TestDirectory) })
                for (var dir = start; dir != null; dir = dir.Parent)
                {
                    string candidate = Path.Combine(dir.FullName, "shared", relativePath);
                    if (File.Exists(candidate)) return candidate;
                }
            SharedFolder.Missing("shared/" + relativePath + " is not beside this repository (it lives in the project's shared folder, not in the package)");
            return null;
        }

        static DirectoryInfo ThisDirectory()
        {
            string source = SourcePath();
            if (string.IsNullOrEmpty(source)) return null;
            var directory = Path.GetDirectoryName(Path.GetFullPath(source));
            return directory != null && Directory.Exists(directory) ? new DirectoryInfo(directory) : null;
        }

        static string SourcePath([CallerFilePath] string path = "") => path;
    }
}
