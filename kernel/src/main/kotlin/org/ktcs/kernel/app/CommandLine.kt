package org.ktcs.kernel.app

import org.ktcs.kernel.bench.BenchOptions
import org.ktcs.kernel.bench.ClientKind
import org.ktcs.kernel.bench.Workload
import java.nio.file.Path

/** What the user asked `ktcs` to do. */
sealed interface Command {
    /** Start the kernel. */
    data class Run(val options: RunOptions) : Command

    /** Print the effective configuration. */
    data class ShowConfig(val options: RunOptions) : Command

    /** Print the documented config file with every default. */
    data object ConfigTemplate : Command

    /** Print the configuration reference page (docs/configuration.md). */
    data object ConfigReference : Command

    /** Check a plant-model file and print a summary. */
    data class CheckModel(val file: Path) : Command

    /** Read a plant-model file of any supported version and write it as 7.0.0. */
    data class ConvertModel(val input: Path, val output: Path) : Command

    /** Generate a benchmark plant ([kind] `grid` or `warehouse`) and write it as a 7.0.0 model file. */
    data class GenerateModel(val plant: GeneratedPlant, val output: Path) : Command

    /** Run the kernel with loopback vehicles on random orders and print figures. */
    data class Simulate(val options: SimulateOptions) : Command

    /** Drive a kTCS through its web API like an external client and print figures. */
    data class Bench(val options: BenchOptions) : Command

    data object BenchHelp : Command

    data object Help : Command

    data object Version : Command
}

/** Options shared by the commands that start or configure the kernel. */
data class RunOptions(val model: Path? = null, val configFile: Path? = null, val overrides: List<String> = emptyList())

/** What `ktcs simulate` runs: a model file or a generated grid, a fleet size, a number of orders, a seed. */
data class SimulateOptions(
    val run: RunOptions = RunOptions(),
    val grid: Pair<Int, Int>? = null,
    val warehouse: Pair<Int, Int>? = null,
    val vehicles: Int? = null,
    val realTime: Boolean = false,
    val timeFactor: Double? = null,
    val orders: Int = 100,
    val seed: Long = 1,
)

/** A generated benchmark plant: `grid` (issue #11's one-way traffic grid) or `warehouse`, its size and fleet. */
data class GeneratedPlant(val kind: String, val width: Int, val height: Int, val vehicles: Int)

/** A mistake on the command line; the message is one line. */
class UsageException(message: String) : RuntimeException(message)

object CommandLine {
    val usage: String = """
        |Usage: ktcs [run] [--model FILE] [--config FILE] [--set key=value]...
        |       ktcs config [--config FILE] [--set key=value]...   print the effective configuration
        |       ktcs config defaults                               print a config file listing every default
        |       ktcs config reference                              print the configuration reference (Markdown)
        |       ktcs model check FILE                              check a plant-model file
        |       ktcs model convert IN OUT                          convert a plant-model file to version 7.0.0
        |       ktcs model generate grid|warehouse WxH [--vehicles N] OUT
        |                                                          write a generated benchmark plant
        |       ktcs simulate [--model FILE | --grid WxH | --warehouse WxH] [--vehicles N] [--orders M] [--seed S]
        |                     [--virtual-time | --real-time] [--time-factor F] [--set key=value]...
        |                                                          benchmark the kernel with simulated vehicles
        |       ktcs bench [demo | batch | restart | soak] [--model FILE] [--runs N] [--url URL [--pid PID]] [--orders N] ...
        |                                                          measure a running kTCS through its web API
        |                                                          (ktcs bench --help lists every option)
        |       ktcs --help | --version
        |
        |Without --model, kTCS loads the model last published (PUT /v1/plantModel, the overview's modelling mode),
        |kept as plant-model.xml in kernel.dataDirectory, else its demo plant. Without --config, it reads
        |config/ktcs.conf if that exists.
    """.trimMargin()

    fun parse(args: List<String>): Command = when (args.firstOrNull()) {
        null -> Command.Run(parseRunOptions(emptyList()))

        "run" -> Command.Run(parseRunOptions(args.drop(1)))

        "config" -> when (args.getOrNull(1)) {
            "defaults" -> Command.ConfigTemplate
            "reference" -> Command.ConfigReference
            else -> Command.ShowConfig(parseRunOptions(args.drop(1)))
        }

        "model" -> parseModelCommand(args.drop(1))

        "simulate" -> Command.Simulate(parseSimulateOptions(args.drop(1)))

        "bench" -> if (args.drop(1).any { it == "--help" || it == "-h" }) {
            Command.BenchHelp
        } else {
            Command.Bench(parseBenchOptions(args.drop(1)))
        }

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

        "generate" -> parseGenerate(args.drop(1))

        null -> throw UsageException("'model' needs a subcommand: check, convert or generate")

        else -> throw UsageException(
            "unknown model subcommand '${args.first()}': expected check, convert or generate",
        )
    }

    private fun parseGenerate(args: List<String>): Command {
        val form = "model generate grid|warehouse WxH [--vehicles N] OUT"
        var vehicles: Int? = null
        val plain = ArrayList<String>()
        val rest = args.iterator()
        while (rest.hasNext()) {
            val arg = rest.next()
            when {
                arg == "--vehicles" -> vehicles = positive(arg, if (rest.hasNext()) rest.next() else "")
                arg.startsWith("--vehicles=") -> vehicles = positive("--vehicles", arg.substringAfter('='))
                arg.startsWith("--") -> throw UsageException("unknown option '$arg'")
                else -> plain += arg
            }
        }
        val (kind, size, output) = exactly(plain, 3, form)
        if (kind !in GENERATED_KINDS) throw UsageException("unknown plant kind '$kind': expected grid or warehouse")
        val (width, height) = parseSize(size, "model generate")
        return Command.GenerateModel(GeneratedPlant(kind, width, height, vehicles ?: 10), Path.of(output))
    }

    private fun exactly(args: List<String>, count: Int, form: String): List<String> {
        if (args.size != count) throw UsageException("expected '$form', got ${args.size} argument(s)")
        return args
    }

    private fun parseSimulateOptions(args: List<String>): SimulateOptions {
        var options = SimulateOptions()
        forEachOption(args) { name, value ->
            options = when (name) {
                "--model" -> options.copy(run = options.run.copy(model = Path.of(value())))

                "--config" -> options.copy(run = options.run.copy(configFile = Path.of(value())))

                "--set" -> options.copy(run = options.run.copy(overrides = options.run.overrides + value()))

                "--grid" -> options.copy(grid = parseSize(value(), name))

                "--warehouse" -> options.copy(warehouse = parseSize(value(), name))

                "--real-time" -> options.copy(realTime = true)

                "--time-factor" -> options.copy(
                    timeFactor = value().toDoubleOrNull()?.takeIf { it > 0 && it.isFinite() }
                        ?: throw UsageException("--time-factor expects a positive number"),
                )

                "--vehicles" -> options.copy(vehicles = positive(name, value()))

                "--orders" -> options.copy(orders = positive(name, value()))

                "--seed" -> options.copy(
                    seed = value().toLongOrNull() ?: throw UsageException("--seed expects a whole number"),
                )

                "--virtual-time" -> options.copy(realTime = false)

                else -> throw UsageException("unknown option '$name'")
            }
        }
        if (listOfNotNull(options.run.model, options.grid, options.warehouse).size > 1) {
            throw UsageException("give only one of --model, --grid and --warehouse")
        }
        return options
    }

    /** Calls [handle] for each `--name value` or `--name=value`; `value()` takes the value when the option has one. */
    private fun forEachOption(args: List<String>, handle: (name: String, value: () -> String) -> Unit) {
        val rest = args.iterator()
        while (rest.hasNext()) {
            val option = rest.next()
            val (name, inline) = option.split('=', limit = 2).let { it[0] to it.getOrNull(1) }
            handle(name) { inline ?: if (rest.hasNext()) rest.next() else throw UsageException("$name needs a value") }
        }
    }

    val benchUsage: String = """
        |Usage: ktcs bench [demo | batch | restart | soak] [options]
        |  demo    start-up, memory, kernel CPU per finished order (--cpu-batches), order creation with 1 and 8
        |          clients (--posts each), GET /v1/transportOrders with --pool orders (issue #12's workload)
        |  batch   --orders orders posted at once; finished/failed, CPU per order, makespan and its lower bound,
        |          assignment latency, deadlock notifications, double allocations and shared positions
        |  restart a state store with --stored-final final and --stored-open open orders; seconds until the
        |          restarted kTCS's web API answers (issue #18)
        |  soak    --hours of plant operation in --minutes (the loopback time factor follows), durability COMMIT,
        |          the fleet kept busy, final orders swept after --keep-hours; prints per plant hour the store's
        |          size and rows per table, RSS, heap after GC, orders finished and swept (issue #18)
        |Options:
        |  --model FILE          plant the orders come from and the started kTCS loads (default: the demo plant)
        |  --grid WxH            a generated one-way grid plant instead of --model (as ktcs simulate --grid)
        |  --vehicles N          vehicles of the started kTCS, each placed on a free point (default: the model's)
        |  --runs N              runs, each with a fresh kTCS; figures print as median (min, max) (default 1)
        |  --url URL             measure a kTCS that runs already (e.g. http://127.0.0.1:55200) instead of starting one
        |  --pid PID             its process id, for CPU and memory figures
        |  --launcher FILE       the ktcs launcher to start (default ./ktcs), always with --no-build
        |  --port N              web port of the started kTCS (default: a free one)
        |  --time-factor F       loopback.timeFactor of the started kTCS (default 100)
        |  --set key=value       a further setting for the started kTCS
        |  --seed S              seed of the random orders (default 1)
        |  --cpu-batches N,M     demo: batch sizes for CPU per finished order (default 50,200)
        |  --posts N             demo: POSTs per creation measurement (default 500)
        |  --client jdk,raw      demo: the clients creation is measured with, in turn (default both): jdk, the
        |                        JDK's HttpClient; raw, a lean one (keep-alive sockets, requests encoded beforehand)
        |  --pool N              demo: orders in the pool when listing them (default 3570)
        |  --gets N              demo: GET requests timed (default 50)
        |  --orders N            batch: orders posted at once (default 200)
        |  --operating-time MS   batch: simulated ms per operation, for the lower bound (default 5000)
        |  --stall-timeout S     seconds without a finished order that end a run (default 60)
        |  --stored-final N      restart: final orders in the store (default 100000)
        |  --stored-open N       restart: DISPATCHABLE orders in the store (default 1000)
        |  --hours H             soak: plant hours run (default 24)
        |  --minutes M           soak: wall-clock minutes they take; time factor = H*60/M (default 40)
        |  --keep-hours K        soak: plant hours a final order is kept before the sweep removes it (default 1)
    """.trimMargin()

    private fun parseBenchOptions(args: List<String>): BenchOptions {
        var options = BenchOptions()
        val rest = when (args.firstOrNull()) {
            "demo" -> args.drop(1)
            "batch" -> args.drop(1).also { options = options.copy(workload = Workload.BATCH) }
            "restart" -> args.drop(1).also { options = options.copy(workload = Workload.RESTART) }
            "soak" -> args.drop(1).also { options = options.copy(workload = Workload.SOAK) }
            else -> args
        }
        forEachOption(rest) { name, value ->
            options = when (name) {
                "--model" -> options.copy(model = Path.of(value()))

                "--grid" -> options.copy(grid = parseSize(value(), name))

                "--runs" -> options.copy(runs = positive(name, value()))

                "--vehicles" -> options.copy(vehicles = positive(name, value()))

                "--url" -> options.copy(url = value())

                "--pid" -> options.copy(pid = positive(name, value()).toLong())

                "--launcher" -> options.copy(launcher = Path.of(value()))

                "--port" -> options.copy(port = positive(name, value()))

                "--time-factor" -> options.copy(timeFactor = positiveDecimal(name, value()))

                "--set" -> options.copy(settings = options.settings + value())

                "--seed" -> options.copy(
                    seed = value().toLongOrNull() ?: throw UsageException("--seed expects a whole number"),
                )

                "--cpu-batches" -> options.copy(cpuBatches = value().split(',').map { positive(name, it.trim()) })

                "--posts" -> options.copy(posts = positive(name, value()))

                "--client" -> options.copy(clientKinds = value().split(',').map { clientKind(it.trim()) })

                "--pool" -> options.copy(poolSize = positive(name, value()))

                "--gets" -> options.copy(gets = positive(name, value()))

                "--orders" -> options.copy(orders = positive(name, value()))

                "--operating-time" -> options.copy(operatingMillis = positive(name, value()).toLong())

                "--stall-timeout" -> options.copy(stallSeconds = positiveDecimal(name, value()))

                "--stored-final" -> options.copy(storedFinal = positive(name, value()))

                "--stored-open" -> options.copy(storedOpen = positive(name, value()))

                "--hours" -> options.copy(soakHours = positiveDecimal(name, value()))

                "--minutes" -> options.copy(soakMinutes = positiveDecimal(name, value()))

                "--keep-hours" -> options.copy(keepHours = positiveDecimal(name, value()))

                else -> throw UsageException("unknown bench option '$name' (ktcs bench --help lists them)")
            }
        }
        if (options.model != null && options.grid != null) {
            throw UsageException("give either --model or --grid, not both")
        }
        if (options.url != null && options.workload in setOf(Workload.RESTART, Workload.SOAK)) {
            throw UsageException("bench ${options.workload.name.lowercase()} starts its own kTCS; not with --url")
        }
        if (options.url?.startsWith("https:", ignoreCase = true) == true && ClientKind.RAW in options.clientKinds) {
            throw UsageException("the raw client speaks plain HTTP: with an https --url give --client jdk")
        }
        if (options.url != null && options.grid != null) {
            throw UsageException("--grid builds a plant for a kTCS the bench starts; not with --url")
        }
        return options
    }

    private fun clientKind(text: String): ClientKind =
        ClientKind.entries.firstOrNull { it.name.equals(text, ignoreCase = true) }
            ?: throw UsageException("--client expects jdk, raw or both separated by a comma, got '$text'")

    private fun positiveDecimal(name: String, text: String): Double =
        text.toDoubleOrNull()?.takeIf { it > 0 } ?: throw UsageException("$name expects a positive number, got '$text'")

    private val GENERATED_KINDS = setOf("grid", "warehouse")

    private fun parseSize(text: String, what: String): Pair<Int, Int> {
        val parts = text.lowercase().split('x')
        val size = parts.mapNotNull { it.toIntOrNull() }
        if (parts.size != 2 || size.size != 2 || size.any { it < 3 }) {
            throw UsageException("$what expects WIDTHxHEIGHT with both at least 3, e.g. 40x40, got '$text'")
        }
        return size[0] to size[1]
    }

    private fun positive(name: String, text: String): Int =
        text.toIntOrNull()?.takeIf { it > 0 }
            ?: throw UsageException("$name expects a positive whole number, got '$text'")

    private fun parseRunOptions(args: List<String>): RunOptions {
        var options = RunOptions()
        forEachOption(args) { name, value ->
            options = when (name) {
                "--model" -> options.copy(model = Path.of(value()))
                "--config" -> options.copy(configFile = Path.of(value()))
                "--set" -> options.copy(overrides = options.overrides + value())
                else -> throw UsageException("unknown option '$name'")
            }
        }
        return options
    }
}
