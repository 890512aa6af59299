using System;
using System.Globalization;
using UnityEditor;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Inspector of <see cref="PseudoHapticWeight"/>: the mass, weight and gain the core derives from this
    /// object's settings, the gain-vs-mass curve of its profile with this object marked, and, in play mode,
    /// the live hold. Every number is the core's (a preview <see cref="WeightSolver"/> is configured here).
    /// </summary>
    [CustomEditor(typeof(PseudoHapticWeight))]
    [CanEditMultipleObjects]
    public sealed class PseudoHapticWeightEditor : UnityEditor.Editor
    {
        const int CurvePoints = 96;
        const double MinMassKg = 0.01, MaxMassKg = 10;
        const float CurveHeight = 150f;

        readonly Vector3[] _curve = new Vector3[CurvePoints];
        readonly double[] _gains = new double[CurvePoints];
        WeightProfile _curveProfile;
        double _curveSpeed = double.NaN;

        public override bool RequiresConstantRepaint() => Application.isPlaying;

        public override void OnInspectorGUI()
        {
            DrawDefaultInspector();
            if (targets.Length > 1) return;
            var weight = (PseudoHapticWeight)target;

            EditorGUILayout.Space();
            EditorGUILayout.LabelField("Weight (computed by the core)", EditorStyles.boldLabel);
            if (!weight.TryCreateModel(out WeightModel model, out string error) || !weight.TryGetProfile(out WeightProfile profile, out error))
            {
                EditorGUILayout.HelpBox(error, MessageType.Error);
                return;
            }
            double speed = weight.ResolveStandardSpeed();
            WeightSolver preview;
            try { preview = new WeightSolver(model, profile, speed); }
            catch (ArgumentException e)
            {
                EditorGUILayout.HelpBox(e.Message, MessageType.Error);
                return;
            }

            EditorGUILayout.LabelField("Mass", F(model.MassKg, "0.###") + " kg");
            EditorGUILayout.LabelField("Weight W = m·g", F(model.WeightNewtons, "0.###") + " N");
            EditorGUILayout.LabelField("W_std / W", F(model.StandardWeightRatio, "0.###"));
            EditorGUILayout.LabelField("Gain G", F(preview.Gain, "0.###") + (preview.Gain < 1 ? "  (lags the hand)" : preview.Gain > 1 ? "  (leads the hand)" : ""));
            EditorGUILayout.LabelField("Standard speed v_std", F(speed, "0.###") + " m/s"
                + (weight.SpeedSource == StandardSpeedSource.UserCalibration && UserCalibrationStore.Current == null ? "  (default: not calibrated)" : ""));
            EditorGUILayout.LabelField("Profile", profile.ToString(), EditorStyles.wordWrappedMiniLabel);
            TwoHands twoHands = profile.Find<TwoHands>();
            BreakAway breakAway = profile.Find<BreakAway>();
            EditorGUILayout.LabelField("x / z", profile.Has<LateralInertia>() ? "the solver's (lateral inertia: trails the hand)" : "the grab's (follows the hand)");
            EditorGUILayout.LabelField("Each of two hands carries", F(model.MassKg * (twoHands != null ? twoHands.Share : 1), "0.###") + " kg"
                + (twoHands != null ? "" : "  (no Two Hands effect: the whole mass)"));
            EditorGUILayout.LabelField("Break-away", breakAway == null ? "off" : (profile.Has<OffsetCorrection>() ? "a strain of " : "a pull of ")
                + F(breakAway.Distance * 100, "0.#") + " cm, two poses in a row");

            DrawCurve(profile, speed, model.MassKg, preview.Gain);

            if (Application.isPlaying)
            {
                EditorGUILayout.Space();
                EditorGUILayout.LabelField("Live", EditorStyles.boldLabel);
                EditorGUILayout.LabelField("Held", weight.IsHeld ? "yes" : "no");
                if (weight.IsHeld)
                {
                    EditorGUILayout.LabelField("Hand − object", F(weight.Offset * 100, "0.0") + " cm");
                    EditorGUILayout.LabelField("Hand y / object y", F(weight.Solver.HandY, "0.000") + " / " + F(weight.Solver.ObjectY, "0.000") + " m");
                    WeightSolver3D solver = weight.Hold.Solver3D;
                    EditorGUILayout.LabelField("Hands on / followed / carrying", weight.Hold.HandCount + " / " + solver.FollowedHands + " / " + solver.HoldingHands
                        + "  (each carries " + F(solver.PerHandMassKg, "0.###") + " kg)");
                    EditorGUILayout.LabelField("Lateral lag x / z", F(solver.LagX * 100, "0.0") + " / " + F(solver.LagZ * 100, "0.0") + " cm");
                }
                if (weight.ConfigurationError != null) EditorGUILayout.HelpBox(weight.ConfigurationError, MessageType.Error);
            }
        }

        void DrawCurve(WeightProfile profile, double speed, double massKg, double gain)
        {
            if (!ReferenceEquals(profile, _curveProfile) || speed != _curveSpeed)
            {
                for (int i = 0; i < CurvePoints; i++)
                    _gains[i] = new WeightSolver(WeightModel.FromMass(MassAt(i / (CurvePoints - 1.0))), profile, speed).Gain;
                _curveProfile = profile;
                _curveSpeed = speed;
            }

            EditorGUILayout.Space();
            EditorGUILayout.LabelField("Gain vs. mass (" + profile.Name + ")", EditorStyles.miniBoldLabel);
            Rect rect = EditorGUILayout.GetControlRect(false, CurveHeight);
            rect.xMin += 28;
            rect.yMax -= 14;
            if (Event.current.type != EventType.Repaint) return;

            double maxGain = Math.Max(1.0, profile.Limits.MaxGain) * 1.05;
            EditorGUI.DrawRect(rect, new Color(0.16f, 0.16f, 0.16f));
            float y1 = GainY(rect, 1.0, maxGain);
            EditorGUI.DrawRect(new Rect(rect.x, y1, rect.width, 1), new Color(1, 1, 1, 0.25f));
            GUI.Label(new Rect(rect.x - 28, y1 - 8, 26, 16), "G=1", EditorStyles.miniLabel);
            GUI.Label(new Rect(rect.x - 28, rect.y - 2, 26, 16), F(maxGain / 1.05, "0.#"), EditorStyles.miniLabel);

            for (double m = MinMassKg; m <= MaxMassKg * 1.0001; m *= 10)
            {
                float x = MassX(rect, m);
                EditorGUI.DrawRect(new Rect(x, rect.y, 1, rect.height), new Color(1, 1, 1, 0.12f));
                GUI.Label(new Rect(x - 14, rect.yMax, 40, 14), m < 1 ? F(m * 1000, "0") + " g" : F(m, "0") + " kg", EditorStyles.miniLabel);
            }

            float golf = MassX(rect, PhysicalConstants.StandardMassKg);
            EditorGUI.DrawRect(new Rect(golf, rect.y, 1, rect.height), new Color(0.4f, 0.8f, 0.4f, 0.6f));

            for (int i = 0; i < CurvePoints; i++)
                _curve[i] = new Vector3(rect.x + rect.width * i / (CurvePoints - 1f), GainY(rect, _gains[i], maxGain), 0);
            Handles.color = new Color(0.35f, 0.7f, 1f);
            Handles.DrawAAPolyLine(2f, _curve);

            float mx = MassX(rect, Math.Min(Math.Max(massKg, MinMassKg), MaxMassKg));
            float my = GainY(rect, gain, maxGain);
            EditorGUI.DrawRect(new Rect(mx, rect.y, 1, rect.height), new Color(1f, 0.6f, 0.2f, 0.7f));
            EditorGUI.DrawRect(new Rect(mx - 3, my - 3, 7, 7), new Color(1f, 0.6f, 0.2f));
            GUI.Label(new Rect(Math.Min(mx + 5, rect.xMax - 90), Math.Max(my - 16, rect.y), 90, 16), "this: G=" + F(gain, "0.00"), EditorStyles.miniLabel);
        }

        static double MassAt(double u) => MinMassKg * Math.Pow(MaxMassKg / MinMassKg, u);

        static float MassX(Rect r, double massKg) =>
            r.x + r.width * (float)(Math.Log(massKg / MinMassKg) / Math.Log(MaxMassKg / MinMassKg));

        static float GainY(Rect r, double gain, double maxGain) =>
            r.yMax - r.height * (float)(Math.Min(Math.Max(gain, 0), maxGain) / maxGain);

        static string F(double v, string format) => v.ToString(format, CultureInfo.InvariantCulture);

        /// <summary>Play mode: the live hand–object offset of a held object, as a vertical bar from the object to the hand's height.</summary>
        [DrawGizmo(GizmoType.Selected | GizmoType.NonSelected)]
        static void DrawOffset(PseudoHapticWeight weight, GizmoType type)
        {
            if (!Application.isPlaying || !weight.IsHeld) return;
            Vector3 obj = weight.transform.position;
            Vector3 hand = weight.HandWorldPosition;
            var level = new Vector3(obj.x, hand.y, obj.z);
            Gizmos.color = weight.Offset >= 0 ? new Color(1f, 0.55f, 0.1f) : new Color(0.3f, 0.7f, 1f);
            Gizmos.DrawLine(obj, level);
            Gizmos.DrawWireSphere(hand, 0.015f);
            Gizmos.color = new Color(1, 1, 1, 0.4f);
            Gizmos.DrawLine(level, hand);
            Handles.Label(Vector3.Lerp(obj, level, 0.5f), " " + F(weight.Offset * 100, "0.0") + " cm");
        }
    }
}
