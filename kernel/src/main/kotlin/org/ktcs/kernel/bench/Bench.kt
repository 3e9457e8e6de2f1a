package org.ktcs.kernel.bench

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.app.GeneratedPlant
import org.ktcs.kernel.app.ModelTools
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.persistence.PlantModelFiles
import org.ktcs.kernel.simulation.Fleet
import org.ktcs.kernel.simulation.LowerBound
import java.io.File
import java.io.PrintStream
import java.net.ServerSocket
import java.nio.file.Files
import java.nio.file.Path

/**
 * `ktcs bench`: drives a kTCS through its web API v1 like an external client and prints one `name: value` line per
 * figure (median, min and max over the runs). Each run starts a fresh kTCS unless [BenchOptions.url] names one.
 */
class Bench(private val options: BenchOptions, private val out: PrintStream, private val err: PrintStream) {
    fun run(): Int {
        val loaded = options.grid
            ?.let { (width, height) ->
                ModelTools.generated(GeneratedPlant("grid", width, height, options.vehicles ?: 10))
            }
            ?: PlantModelLoader.load(options.model).model
        // A started kTCS gets the fleet asked for, each vehicle on a point of its own, as `ktcs simulate` places them.
        val model = if (options.url == null) {
            Fleet.withVehicles(loaded, options.vehicles ?: loaded.vehicles.size.coerceAtLeast(1))
        } else {
            loaded
        }
        val modelFile = if (options.url == null) preparedModelFile(model) else null
        val figures = Figures()
        figures.note("workload", options.workload.name.lowercase())
        figures.note("plant", model.name)
        figures.note(
            "kernel",
            options.url
                ?: "started by the bench: ${options.launcher} --no-build, loopback.timeFactor=${options.timeFactor}",
        )
        val log = File.createTempFile("ktcs-bench-", ".log")
        repeat(options.runs) { index ->
            err.println("ktcs bench: run ${index + 1} of ${options.runs} (kTCS output: $log)")
            val prefix = "Bench-${System.currentTimeMillis().toString(RADIX)}"
            if (options.workload == Workload.RESTART) {
                RestartWorkload(options, figures).run(model, modelFile, log) { settings ->
                    val port = options.port.takeIf { it > 0 } ?: ServerSocket(0).use { it.localPort }
                    KtcsUnderTest.start(
                        options.launcher,
                        modelFile,
                        port,
                        options.timeFactor,
                        log,
                        settings + options.settings,
                    )
                }
                return@repeat
            }
            if (options.workload == Workload.SOAK) {
                soak(model, modelFile, log, figures)
                return@repeat
            }
            open(log, modelFile).use { ktcs ->
                val orders = BenchOrders(model, options.seed + index)
                when (options.workload) {
                    Workload.DEMO -> DemoWorkload(options, figures).run(ktcs, orders, prefix)

                    Workload.RESTART, Workload.SOAK -> Unit

                    Workload.BATCH -> BatchWorkload(
                        options,
                        figures,
                    ).run(ktcs, orders, LowerBound(model, options.operatingMillis), prefix)
                }
            }
        }
        figures.print(out)
        return 0
    }

    /**
     * The kTCS to measure, ready. A started one whose port was taken meanwhile (ports in the ephemeral range may be
     * held by any client connection on the machine) is started again on the next port.
     */
    private fun open(log: File, modelFile: Path?): KtcsUnderTest {
        options.url?.let { return KtcsUnderTest.connect(it, options.pid).also { it.awaitReady(READY_SECONDS) } }
        var attempt = 0
        val firstPort = options.port.takeIf { it > 0 } ?: ServerSocket(0).use { it.localPort }
        while (true) {
            val port = firstPort + attempt
            val ktcs = KtcsUnderTest.start(options.launcher, modelFile, port, options.timeFactor, log, options.settings)
            try {
                ktcs.awaitReady(READY_SECONDS)
                return ktcs
            } catch (failed: IllegalStateException) {
                ktcs.close()
                if (++attempt >= PORT_ATTEMPTS ||
                    !log.readText().takeLast(LOG_TAIL).contains("Address already in use")
                ) {
                    throw failed
                }
                err.println("ktcs bench: port $port is taken, trying ${port + 1}")
            }
        }
    }

    private fun soak(model: PlantModel, modelFile: Path?, log: File, figures: Figures) {
        val data = Files.createTempDirectory("ktcs-bench-soak")
        try {
            val soak = SoakWorkload(options, figures, out)
            soak.run(model, data) {
                val port = options.port.takeIf { it > 0 } ?: ServerSocket(0).use { it.localPort }
                KtcsUnderTest.start(
                    options.launcher,
                    modelFile,
                    port,
                    soak.timeFactor,
                    log,
                    soak.settings(data) + options.settings,
                )
            }
        } finally {
            data.toFile().deleteRecursively()
        }
    }

    private fun preparedModelFile(model: PlantModel): Path {
        val file = Files.createTempFile("ktcs-bench-plant-", ".xml")
        file.toFile().deleteOnExit()
        PlantModelFiles.write(model, file)
        return file
    }

    private companion object {
        const val RADIX = 36
        const val READY_SECONDS = 120L
        const val PORT_ATTEMPTS = 5
        const val LOG_TAIL = 2000
    }
}
