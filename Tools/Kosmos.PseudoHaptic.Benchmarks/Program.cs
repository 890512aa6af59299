using BenchmarkDotNet.Running;
using Kosmos.PseudoHaptic.Benchmarks;

// What the solver costs per update (issue 4). Every class runs a short job (1 launch, 3 warm-ups, 5 iterations)
// so the whole suite takes minutes on 2 cores. Examples:
//   dotnet run -c Release --project Tools/Kosmos.PseudoHaptic.Benchmarks -- --filter '*'
//   dotnet run -c Release --project Tools/Kosmos.PseudoHaptic.Benchmarks -- --filter '*Batch*'
//   dotnet run -c Release --project Tools/Kosmos.PseudoHaptic.Benchmarks -- --interleaved   (issue 10's cases, alternating)
//   dotnet run -c Release --project Tools/Kosmos.PseudoHaptic.Benchmarks -- --steps paper 20   (for callgrind: StepCount)
//   dotnet run -c Release --project Tools/Kosmos.PseudoHaptic.Benchmarks -- --ablation paper   (each effect taken out in turn: EffectAblation)
//   dotnet run -c Release --project Tools/Kosmos.PseudoHaptic.Benchmarks -- --digest 100   (the bits of every result: ResultDigest)
if (args.Length == 1 && args[0] == "--interleaved") { InterleavedTiming.Run(Console.Out); return; }
if (args.Length == 2 && args[0] == "--ablation") { EffectAblation.Run(args[1], Console.Out); return; }
if (args.Length <= 2 && args.Length > 0 && args[0] == "--digest") { ResultDigest.Run(args.Length == 2 ? int.Parse(args[1]) : 100, Console.Out); return; }
if (args.Length == 3 && args[0] == "--steps") { StepCount.Run(args[1], int.Parse(args[2]), Console.Out); return; }
BenchmarkSwitcher.FromAssembly(typeof(BenchmarkConfig).Assembly).Run(args, new BenchmarkConfig());
