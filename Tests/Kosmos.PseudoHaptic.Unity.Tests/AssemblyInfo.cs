// Every test here runs in a fresh scene of the double, inside a Unity Test Framework log scope.
[assembly: UnityDouble.PlayModeScope]
