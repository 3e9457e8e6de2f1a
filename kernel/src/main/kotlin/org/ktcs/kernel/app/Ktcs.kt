package org.ktcs.kernel.app

import org.ktcs.extension.ExtensionException
import org.ktcs.extension.config.ConfigException
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.bench.Bench
import org.ktcs.kernel.config.ConfigFile
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.config.SettingsCatalogue
import org.ktcs.kernel.extension.Extensions
import org.ktcs.kernel.extension.InstalledExtensions
import org.ktcs.kernel.persistence.ModelFileException
import org.ktcs.kernel.persistence.PublishedModelFile
import org.ktcs.kernel.simulation.Fleet
import org.ktcs.kernel.simulation.SimulationRunner
import org.ktcs.kernel.store.DurableState
import org.ktcs.kernel.validation.InvalidModelException
import org.ktcs.kernel.web.KernelVersion
import java.io.PrintStream
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CompletionException

/** The `ktcs` command: parses the command line, runs one command and returns the process exit code. */
class Ktcs(private val out: PrintStream, private val err: PrintStream, private val environment: Map<String, String>) {
    fun run(args: List<String>, awaitShutdown: (() -> Unit)? = null): Int = try {
        when (val command = CommandLine.parse(args)) {
            is Command.Run -> runKernel(command.options, awaitShutdown)
            is Command.ShowConfig -> 0.also { showConfig(command.options) }
            Command.ConfigTemplate -> 0.also { out.print(ConfigFile.render()) }
            Command.ConfigReference -> 0.also { out.print(ConfigReference.render()) }
            is Command.Simulate -> simulate(command.options)
            is Command.CheckModel -> ModelTools(out).check(command.file)
            is Command.ConvertModel -> ModelTools(out).convert(command.input, command.output)
            is Command.Bench -> Bench(command.options, out, err).run()
            Command.BenchHelp -> 0.also { out.println(CommandLine.benchUsage) }
            is Command.GenerateModel -> ModelTools(out).generate(command.plant, command.output)
            Command.Help -> 0.also { out.println(CommandLine.usage) }
            Command.Version -> 0.also { out.println("kTCS ${KernelVersion.ofThisBuild().version}") }
        }
    } catch (error: UsageException) {
        err.println("ktcs: ${error.message}")
        err.println(CommandLine.usage)
        EXIT_USAGE
    } catch (error: Exception) {
        err.println("ktcs: error: ${oneLine(error) ?: throw error}")
        EXIT_FAILURE
    }

    private fun runKernel(options: RunOptions, awaitShutdown: (() -> Unit)?): Int {
        val signal = if (awaitShutdown == null) ShutdownSignal.install() else null
        val waitForShutdown = awaitShutdown ?: signal!!::await
        // Reading the model is most of the start-up's own work (Jackson's Kotlin module reflects on every element
        // class); it runs while the configuration, logging and extensions are set up.
        val own = ownConfig(options)
        val published = PublishedModelFile(Path.of(own[KtcsSettings.dataDirectory]))
        val loading = CompletableFuture.supplyAsync { PlantModelLoader.loadAtStart(options.model, published) }
        val (config, installed) = configAndExtensions(options, own)
        Logging.apply(config)
        Logging.toFile(config)
        // The state store opens (and is read) meanwhile too.
        val opening = CompletableFuture.supplyAsync { DurableState.open(config) }
        val model = joined(loading)
        withContextClassLoader(installed.classLoader) {
            val application = KernelApplication(
                config,
                model,
                installed.extensions,
                installed::jarOf,
                joined(opening),
            ) { signal?.request() }
            application.start()
            try {
                waitForShutdown()
            } finally {
                application.stop()
            }
        }
        return 0
    }

    private fun <T> joined(future: CompletableFuture<T>): T = try {
        future.join()
    } catch (failed: CompletionException) {
        throw failed.cause ?: failed
    }

    private fun simulate(options: SimulateOptions): Int {
        // The same configuration and timing rules as `ktcs` itself; --time-factor is loopback.timeFactor.
        val timeFactor = listOfNotNull(options.timeFactor?.let { "loopback.timeFactor=$it" })
        val (config, installed) = configAndExtensions(options.run.copy(overrides = options.run.overrides + timeFactor))
        Logging.apply(config)
        Logging.quietNotifications()
        val generated = options.grid?.let { (w, h) -> GeneratedPlant("grid", w, h, options.vehicles ?: 10) }
            ?: options.warehouse?.let { (w, h) -> GeneratedPlant("warehouse", w, h, options.vehicles ?: 10) }
        val plant = generated?.let(ModelTools::generated) ?: PlantModelLoader.load(options.run.model).model
        val model = Fleet.withVehicles(plant, options.vehicles ?: plant.vehicles.size.coerceAtLeast(1))
        val report = withContextClassLoader(installed.classLoader) {
            SimulationRunner(
                model,
                config,
                installed.extensions,
                options.orders,
                options.seed,
                realTime = options.realTime,
            ).run()
        }
        report.lines().forEach(out::println)
        val clean = report.doubleAllocations == 0 && report.sharedPositions == 0 && report.deadlocksDetected == 0
        return if (report.ordersFinished == report.ordersCreated && clean) 0 else EXIT_FAILURE
    }

    private fun showConfig(options: RunOptions) {
        val (config, installed) = configAndExtensions(options)
        out.println(ConfigFile.describe(config, SettingsCatalogue.of(installed.extensions)))
    }

    /** kTCS's own settings alone (an extension's are not known before the extensions are loaded). */
    private fun ownConfig(options: RunOptions): KtcsConfig {
        val file = options.configFile ?: DEFAULT_CONFIG.takeIf { Files.isRegularFile(it) }
        return ConfigLoader(KtcsSettings.all).load(file, environment, options.overrides, ignoreUnknown = true)
    }

    /**
     * The extensions on the class path and in `extensions.directory` (required there if set explicitly), and the
     * configuration, whose keys include the extensions' settings: kTCS's own settings are read first (skipping the
     * others) to find the extensions, then all of them.
     */
    private fun configAndExtensions(
        options: RunOptions,
        own: KtcsConfig = ownConfig(options),
    ): Pair<KtcsConfig, InstalledExtensions> {
        val file = options.configFile ?: DEFAULT_CONFIG.takeIf { Files.isRegularFile(it) }
        val setting = KtcsSettings.extensionsDirectory
        val installed = Extensions.load(Path.of(own[setting]), required = own.sourceOf(setting) != "default")
        val config = ConfigLoader(SettingsCatalogue.of(installed.extensions)).load(file, environment, options.overrides)
        return config to installed
    }

    /**
     * Runs [block] with [loader] as the thread's context class loader, which threads started in it inherit: drivers
     * listed as plain `VehicleDriverFactory` services are found through it, so it must see the extension jars.
     */
    private fun <T> withContextClassLoader(loader: ClassLoader, block: () -> T): T {
        val thread = Thread.currentThread()
        val previous = thread.contextClassLoader
        thread.contextClassLoader = loader
        try {
            return block()
        } finally {
            thread.contextClassLoader = previous
        }
    }

    /** The one-line message for errors a user caused, or `null` for bugs, which keep their stack trace. */
    private fun oneLine(error: Exception): String? = when (error) {
        is ConfigException, is ModelFileException, is ExtensionException -> error.message

        is InvalidModelException -> error.summaryLine()

        is java.net.BindException -> "cannot listen on the configured address: ${error.message}"

        is IllegalArgumentException -> error.message

        // Koin wraps what goes wrong while it creates an extension (a port in use, a bad extension setting).
        else -> generateSequence(error.cause) { it.cause }.firstNotNullOfOrNull { cause ->
            when (cause) {
                is java.net.BindException -> "cannot listen on the configured address: ${cause.message}"
                is ConfigException, is ExtensionException -> cause.message
                else -> null
            }
        }
    }

    companion object {
        const val EXIT_FAILURE = 1
        const val EXIT_USAGE = 2
        val DEFAULT_CONFIG: Path = Path.of("config", "ktcs.conf")
    }
}
