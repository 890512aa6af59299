using System.CommandLine;
namespace Kosmos.PseudoHaptic.Cli.CommandLine;

/// <summary>
/// <c>pseudohaptic completion bash|zsh</c>: prints a script that makes the shell complete the tool's commands,
/// options and choices. The script asks the tool itself through System.CommandLine's <c>[suggest:N]</c> directive,
/// so completion always matches the installed version (no dotnet-suggest needed).
/// </summary>
public static class CompletionCommand
{
    public static CliCommand Define() => new(
        "completion",
        "Print a shell script that completes pseudohaptic's commands and options (bash or zsh): add 'source <(pseudohaptic completion bash)' to ~/.bashrc",
        Run,
        new[] { "pseudohaptic completion bash" },
        Shell());

    static System.CommandLine.Argument<string> Shell()
    {
        var shell = new System.CommandLine.Argument<string>("shell") { Description = "bash or zsh (default bash)", DefaultValueFactory = _ => "bash" };
        System.CommandLine.ArgumentValidation.AcceptOnlyFromAmong(shell, "bash", "zsh");
        return shell;
    }

    const string Bash = """
        # pseudohaptic completion for bash: source <(pseudohaptic completion bash)
        _pseudohaptic_complete() {
            local IFS=$'\n'
            local candidates
            candidates=$(pseudohaptic "[suggest:${COMP_POINT}]" "${COMP_LINE}" 2>/dev/null)
            COMPREPLY=($(compgen -W "${candidates}" -- "${COMP_WORDS[COMP_CWORD]}"))
        }
        complete -o default -o bashdefault -F _pseudohaptic_complete pseudohaptic
        """;

    const string Zsh = """
        # pseudohaptic completion for zsh: source <(pseudohaptic completion zsh)
        autoload -U +X bashcompinit && bashcompinit

        """;

    static int Run(Options o)
    {
        string shell = o.Argument("shell") ?? "bash";
        switch (shell)
        {
            case "bash": Console.Out.WriteLine(Bash); break;
            case "zsh": Console.Out.WriteLine(Zsh + Bash); break;
            default: throw new CliException($"expected bash or zsh, got '{Files.Messages.OneLine(shell)}'");
        }
        return 0;
    }
}
