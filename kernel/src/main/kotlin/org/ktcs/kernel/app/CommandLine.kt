package org.ktcs.kernel.app

import java.nio.file.Path

/** What the user asked `ktcs` to do. */
sealed interface Command {
    /** Start the kernel. */
    data class Run(val options: RunOptions) : Command

    /** Print the effective configuration. */
    data class ShowConfig(val options: RunOptions) : Command

    /** Check a plant-model file and print a summary. */
    data class CheckModel(val file: Path) : Command

    /** Read a plant-model file of any supported version and write it as 7.0.0. */
    data class ConvertModel(val input: Path, val output: Path) : Command

    data object Help : Command

    data object Version : Command
}

/** Options shared by the commands that start or configure the kernel. */
data class RunOptions(val model: Path? = null, val configFile: Path? = null, val overrides: List<String> = emptyList())

/** A mistake on the command line; the message is one line. */
class UsageException(message: String) : RuntimeException(message)

object CommandLine {
    val usage: String = """
        |Usage: ktcs [run] [--model FILE] [--config FILE] [--set key=value]...
        |       ktcs config [--config FILE] [--set key=value]...   print the effective configuration
        |       ktcs model check FILE                              check a plant-model file
        |       ktcs model convert IN OUT                          convert a plant-model file to version 7.0.0
        |       ktcs --help | --version
        |
        |Without --model, kTCS loads its demo plant. Without --config, it reads config/ktcs.conf if that exists.
    """.trimMargin()

    fun parse(args: List<String>): Command = when (args.firstOrNull()) {
        null -> Command.Run(parseRunOptions(emptyList()))

        "run" -> Command.Run(parseRunOptions(args.drop(1)))

        "config" -> Command.ShowConfig(parseRunOptions(args.drop(1)))

        "model" -> parseModelCommand(args.drop(1))

        "-h", "--help", "help" -> Command.Help

        "--version" -> Command.Version

        else -> if (args.first().startsWith("--")) {
            Command.Run(parseRunOptions(args))
        } else {
            throw UsageException("unknown command '${args.first()}'")
        }
    }

    private fun parseModelCommand(args: List<String>): Command = when (args.firstOrNull()) {
        "check" -> Command.CheckModel(Path.of(exactly(args.drop(1), 1, "model check FILE").single()))

        "convert" -> exactly(args.drop(1), 2, "model convert IN OUT").let {
            Command.ConvertModel(Path.of(it[0]), Path.of(it[1]))
        }

        null -> throw UsageException("'model' needs a subcommand: check or convert")

        else -> throw UsageException("unknown model subcommand '${args.first()}': expected check or convert")
    }

    private fun exactly(args: List<String>, count: Int, form: String): List<String> {
        if (args.size != count) throw UsageException("expected '$form', got ${args.size} argument(s)")
        return args
    }

    private fun parseRunOptions(args: List<String>): RunOptions {
        var options = RunOptions()
        val rest = args.iterator()
        while (rest.hasNext()) {
            val option = rest.next()
            val (name, inlineValue) = option.split('=', limit = 2).let { it[0] to it.getOrNull(1) }
            fun value(): String =
                inlineValue ?: if (rest.hasNext()) rest.next() else throw UsageException("$name needs a value")
            options = when (name) {
                "--model" -> options.copy(model = Path.of(value()))
                "--config" -> options.copy(configFile = Path.of(value()))
                "--set" -> options.copy(overrides = options.overrides + value())
                else -> throw UsageException("unknown option '$option'")
            }
        }
        return options
    }
}
