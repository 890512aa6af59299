#!/usr/bin/env bash
# Runs Stryker.NET on one piece of the package (quality.md, "Mutation score"), so that no run needs more than
# about 40 minutes of the shared 2-core machine. The piece's files are given as --mutate globs to the config of
# the assembly they belong to (its test project, additional timeout and mutation level stay as configured).
#
#   Tools/stryker-piece.sh PIECE [extra dotnet-stryker options]
#   Tools/stryker-piece.sh --list
#
# Writes out/stryker/PIECE/ (Stryker's reports: reports/mutation-report.json) and out/stryker/PIECE/run.txt
# (commit, start and end in UTC, the command), which Tools/stryker-summary.py reads. Sets
# PSEUDOHAPTIC_SKIP_SOAK=1 (the ten-hour soak tests skip themselves) and runs at nice 15, concurrency 2 and the
# Release configuration unless --concurrency or --configuration is given after PIECE.
#
# Run it from a git worktree nothing else builds in (git worktree add ../wt-stryker): Stryker restores and
# builds the projects into their obj/ and bin/ folders, and puts the mutated assembly into the test project's
# bin; a build in the same tree during the run breaks its compile (CS0518) or makes every mutant survive.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"

piece_dir() {
  case "$1" in
    logic-*) echo "Tests/Kosmos.PseudoHaptic.Logic" ;;
    evaluation-*) echo "Tests/Kosmos.PseudoHaptic.Evaluation" ;;
    *) echo "Tests/Kosmos.PseudoHaptic.Core" ;;
  esac
}

# The character index (from 0, in characters as Roslyn counts them, not bytes) at which the first line of Runtime/…/FILE
# containing TEXT begins; with TEXT empty, the file's length.
span_at() {
  python3 - "$root/Packages/com.kosmos.pseudohaptic/Runtime/${1#\*\*/Runtime/}" "$2" <<'PY'
import sys
text = open(sys.argv[1], encoding="utf-8-sig").read()
if not sys.argv[2]:
    print(len(text))
    sys.exit(0)
at = text.find(sys.argv[2])
if at < 0:
    sys.exit("stryker-piece: '%s' not found in %s" % (sys.argv[2], sys.argv[1]))
print(text.rfind("\n", 0, at) + 1)
PY
}

# One line per glob; a leading ! excludes.
piece_globs() {
  local c="**/Runtime/Core" l="**/Runtime/Logic" e="**/Runtime/Evaluation"
  case "$1" in
    core-root) printf '%s\n' "$c/*.cs" "!$c/WeightSolver3D.cs" ;;
    effects) printf '%s\n' "$c/Effects/*.cs" ;;
    estimation) printf '%s\n' "$c/Estimation/*.cs" ;;
    calibration-simulation) printf '%s\n' "$c/Calibration/*.cs" "$c/Simulation/*.cs" ;;
    3d) printf '%s\n' "$c/WeightSolver3D.cs" ;;
    profiles) printf '%s\n' "$c/Profiles/*.cs" ;;
    # The parts of the core pieces above that do not fit 40 minutes here: a mutant of a file the solver runs every frame
    # is covered by most of the suite and costs about 40 s of one core (quality.md, "What a mutant costs"), so a part
    # holds about 120 lines of code. Split by file, and WeightSolver.cs by character span (Stryker's -m FILE{from..to})
    # at its pipeline.
    core-solver-1) printf '%s\n' "$c/WeightSolver.cs{0..$(( $(span_at "$c/WeightSolver.cs" 'double RunPipeline(') - 1 ))}" ;;
    core-solver-2) printf '%s\n' "$c/WeightSolver.cs{$(span_at "$c/WeightSolver.cs" 'double RunPipeline(')..$(span_at "$c/WeightSolver.cs" '')}" ;;
    core-types) printf '%s\n' "$c/*.cs" "!$c/WeightSolver.cs" "!$c/WeightSolver3D.cs" ;;
    # core-types took 43 minutes for 355 mutants (sixth session): in two, by file, about 175 mutants each; a file added to
    # the core's root lands in core-types-2.
    core-types-1) printf '%s\n' "$c/PaperLiteralSolver.cs" "$c/WeightProfile.cs" "$c/NamedProfiles.cs" "$c/SolverLimits.cs" \
      "$c/WeightEffect.cs" "$c/LastWeight.cs" ;;
    core-types-2) printf '%s\n' "$c/*.cs" "!$c/WeightSolver.cs" "!$c/WeightSolver3D.cs" "!$c/PaperLiteralSolver.cs" \
      "!$c/WeightProfile.cs" "!$c/NamedProfiles.cs" "!$c/SolverLimits.cs" "!$c/WeightEffect.cs" "!$c/LastWeight.cs" ;;
    # WeightSolver3D.cs in four spans at its methods (its 454 mutants ran at about three a minute: 2.5 hours whole):
    # configuration and the hold's begin, then Begin … Step, Select … Anchor, and StepHorizontal to the end.
    3d-1) printf '%s\n' "$c/WeightSolver3D.cs{0..$(( $(span_at "$c/WeightSolver3D.cs" 'void Begin(in HandPose first') - 1 ))}" ;;
    3d-2) printf '%s\n' "$c/WeightSolver3D.cs{$(span_at "$c/WeightSolver3D.cs" 'void Begin(in HandPose first')..$(( $(span_at "$c/WeightSolver3D.cs" 'void Select(in HandPose first') - 1 ))}" ;;
    3d-3) printf '%s\n' "$c/WeightSolver3D.cs{$(span_at "$c/WeightSolver3D.cs" 'void Select(in HandPose first')..$(( $(span_at "$c/WeightSolver3D.cs" 'void StepHorizontal(') - 1 ))}" ;;
    3d-4) printf '%s\n' "$c/WeightSolver3D.cs{$(span_at "$c/WeightSolver3D.cs" 'void StepHorizontal(')..$(span_at "$c/WeightSolver3D.cs" '')}" ;;
    effects-1) printf '%s\n' "$c/Effects/FasterMovesFurther.cs" "$c/Effects/BreakAway.cs" "$c/Effects/ExperimentalBlend.cs" \
      "$c/Effects/WeightGain.cs" "$c/Effects/TwoHands.cs" ;;
    effects-2) printf '%s\n' "$c/Effects/SpeedCap.cs" "$c/Effects/OffsetCorrection.cs" "$c/Effects/OffsetRelaxation.cs" \
      "$c/Effects/LoweringGuard.cs" ;;
    effects-3) printf '%s\n' "$c/Effects/*.cs" "!$c/Effects/FasterMovesFurther.cs" "!$c/Effects/BreakAway.cs" \
      "!$c/Effects/ExperimentalBlend.cs" "!$c/Effects/WeightGain.cs" "!$c/Effects/TwoHands.cs" "!$c/Effects/SpeedCap.cs" \
      "!$c/Effects/OffsetCorrection.cs" "!$c/Effects/OffsetRelaxation.cs" "!$c/Effects/LoweringGuard.cs" ;;
    estimation-filters) printf '%s\n' "$c/Estimation/*.cs" "!$c/Estimation/PoseDeltaEstimator.cs" "!$c/Estimation/Reach.cs" ;;
    estimation-poses) printf '%s\n' "$c/Estimation/PoseDeltaEstimator.cs" "$c/Estimation/Reach.cs" ;;
    # evaluation-files in two: its run of 707 mutants was stopped after 27 minutes with its test processes idle (the
    # writers' mutants that block a wait run to Stryker's timeout).
    evaluation-writers) printf '%s\n' "$e/AtomicFile.cs" "$e/SaveQueue.cs" ;;
    evaluation-csv) printf '%s\n' "$e/CsvReader.cs" "$e/CsvTable.cs" "$e/ResponsesCsv.cs" "$e/ScoresCsv.cs" \
      "$e/QuestionnaireJson.cs" "$e/TextWrap.cs" "$e/EvaluationFormatException.cs" ;;
    calibration) printf '%s\n' "$c/Calibration/*.cs" ;;
    simulation) printf '%s\n' "$c/Simulation/*.cs" ;;
    logic-grab) printf '%s\n' "$l/ContactSet.cs" "$l/GrabFollow.cs" "$l/GrabSelection.cs" "$l/GrabbingHands.cs" \
      "$l/HandDrawing.cs" "$l/HandGrab.cs" "$l/HeldObject.cs" "$l/PinchDetector.cs" "$l/RigHands.cs" \
      "$l/Vector3d.cs" "$l/VelocityTracker.cs" ;;
    # Every other Logic file (calibration station, field rules, the questionnaire panel's model, the session log, weight
    # and profile settings, …): a file added to Logic lands here unless it is listed above.
    logic-session) printf '%s\n' "$l/*.cs" "!$l/ContactSet.cs" "!$l/GrabFollow.cs" "!$l/GrabSelection.cs" \
      "!$l/GrabbingHands.cs" "!$l/HandDrawing.cs" "!$l/HandGrab.cs" "!$l/HeldObject.cs" "!$l/PinchDetector.cs" \
      "!$l/RigHands.cs" "!$l/Vector3d.cs" "!$l/VelocityTracker.cs" ;;
    evaluation-files) printf '%s\n' "$e/AtomicFile.cs" "$e/SaveQueue.cs" "$e/CsvReader.cs" "$e/CsvTable.cs" \
      "$e/ResponsesCsv.cs" "$e/ScoresCsv.cs" "$e/QuestionnaireJson.cs" "$e/TextWrap.cs" \
      "$e/EvaluationFormatException.cs" ;;
    evaluation-questionnaire) printf '%s\n' "$e/*.cs" "!$e/AtomicFile.cs" "!$e/SaveQueue.cs" "!$e/CsvReader.cs" \
      "!$e/CsvTable.cs" "!$e/ResponsesCsv.cs" "!$e/ScoresCsv.cs" "!$e/QuestionnaireJson.cs" "!$e/TextWrap.cs" \
      "!$e/EvaluationFormatException.cs" ;;
    evaluation-psychometrics) printf '%s\n' "$e/Psychophysics/Distributions.cs" "$e/Psychophysics/PairedTests.cs" \
      "$e/Psychophysics/PsychometricAnalysis.cs" "$e/Psychophysics/PsychometricBootstrap.cs" \
      "$e/Psychophysics/PsychometricFit.cs" "$e/Psychophysics/SeededRandom.cs" \
      "$e/Psychophysics/SimulatedObserver.cs" ;;
    # evaluation-psychometrics in three (its 965 mutants ran 99 minutes unfinished): the distributions and paired tests,
    # the fit, and the rest (analysis, bootstrap, random numbers, simulated observer).
    evaluation-psychometrics-1) printf '%s\n' "$e/Psychophysics/Distributions.cs" "$e/Psychophysics/PairedTests.cs" ;;
    evaluation-psychometrics-2) printf '%s\n' "$e/Psychophysics/PsychometricFit.cs" ;;
    evaluation-psychometrics-3) printf '%s\n' "$e/Psychophysics/PsychometricAnalysis.cs" "$e/Psychophysics/PsychometricBootstrap.cs" \
      "$e/Psychophysics/SeededRandom.cs" "$e/Psychophysics/SimulatedObserver.cs" ;;
    evaluation-discrimination) printf '%s\n' "$e/Psychophysics/*.cs" "!$e/Psychophysics/Distributions.cs" \
      "!$e/Psychophysics/PairedTests.cs" "!$e/Psychophysics/PsychometricAnalysis.cs" \
      "!$e/Psychophysics/PsychometricBootstrap.cs" "!$e/Psychophysics/PsychometricFit.cs" \
      "!$e/Psychophysics/SeededRandom.cs" "!$e/Psychophysics/SimulatedObserver.cs" ;;
    *) return 1 ;;
  esac
}

pieces="core-root effects estimation calibration-simulation 3d profiles logic-grab logic-session evaluation-files
evaluation-questionnaire evaluation-psychometrics evaluation-discrimination
core-solver-1 core-solver-2 core-types core-types-1 core-types-2 3d-1 3d-2 3d-3 3d-4 effects-1 effects-2 effects-3 estimation-filters estimation-poses calibration simulation evaluation-writers evaluation-csv evaluation-psychometrics-1 evaluation-psychometrics-2 evaluation-psychometrics-3"

if [ "${1:-}" = "--list" ]; then
  for p in $pieces; do
    printf '%s (%s):' "$p" "$(piece_dir "$p")"
    while IFS= read -r g; do printf ' -m "%s"' "$g"; done < <(piece_globs "$p")
    printf '\n'
  done
  exit 0
fi

piece="${1:-}"
if [ -z "$piece" ] || ! piece_globs "$piece" > /dev/null; then
  echo "stryker-piece: PIECE must be one of: $(echo $pieces) (got '${piece}')" >&2
  exit 2
fi
shift

args=(--output "$root/out/stryker/$piece")
case " $* " in *" --concurrency "*|*" -c "*) ;; *) args+=(--concurrency 2) ;; esac
# Release: the edit-mode suite runs in 19 s instead of Debug's 27 s, and each mutant pays its covering tests' time.
case " $* " in *" --configuration "*) ;; *) args+=(--configuration Release) ;; esac
while IFS= read -r g; do args+=(-m "$g"); done < <(piece_globs "$piece")

mkdir -p "$root/out/stryker/$piece"
meta="$root/out/stryker/$piece/run.txt"
{
  echo "piece: $piece"
  echo "commit: $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- Packages Tests || echo ' (uncommitted changes)')"
  echo "start: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "command: cd $(piece_dir "$piece") && PSEUDOHAPTIC_SKIP_SOAK=1 dotnet stryker ${args[*]} $*"
} > "$meta"

cd "$root/$(piece_dir "$piece")"
status=0
PSEUDOHAPTIC_SKIP_SOAK=1 nice -n 15 dotnet stryker "${args[@]}" "$@" || status=$?
echo "end: $(date -u +%Y-%m-%dT%H:%M:%SZ)" >> "$meta"
echo "exit: $status" >> "$meta"
exit $status
