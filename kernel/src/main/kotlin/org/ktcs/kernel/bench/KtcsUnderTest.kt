package org.ktcs.kernel.bench

import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit

/**
 * The kTCS the bench measures: either one it starts itself (`ktcs --no-build`, so the figures are those of the
 * launcher a user runs) or one already running at a URL, whose process the bench then only knows if given its id.
 */
class KtcsUnderTest private constructor(
    val client: BenchClient,
    private val process: Process?,
    val pid: Long?,
    private val startNanos: Long,
    private val port: Int? = null,
    private val dataDirectory: Path? = null,
) : AutoCloseable {
    /** Seconds from starting the process to the web API answering with every vehicle idle; set by [awaitReady]. */
    var readySeconds: Double? = null
        private set

    /** `/proc` figures of the kTCS process, `null` when its process is unknown. */
    val stats: ProcStats? = pid?.let(::ProcStats)

    /**
     * Waits until the web API answers and every vehicle is idle (procState IDLE, not moving); returns the seconds
     * since the process was started.
     */
    fun awaitReady(timeoutSeconds: Long): Double {
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutSeconds)
        while (System.nanoTime() < deadline) {
            if (process != null && !process.isAlive) {
                error("kTCS exited with code ${process.exitValue()} before it was ready")
            }
            // Connecting to a local port nobody listens on yet can make the kernel hand the client that very port as
            // its own (TCP self-connect), and kTCS then finds its port taken: ask only once it listens.
            val vehicles = if (port == null || isListening(port)) client.vehicles() else null
            if (vehicles != null &&
                vehicles.all { it.string("procState") == "IDLE" && it.string("state") != "EXECUTING" }
            ) {
                return ((System.nanoTime() - startNanos) / NANOS_PER_SECOND).also { readySeconds = it }
            }
            Thread.sleep(READY_POLL_MILLIS)
        }
        error("kTCS was not ready (web API answering, vehicles idle) within $timeoutSeconds s")
    }

    /** Waits until the web API answers (whatever the vehicles do); returns the seconds since the process started. */
    fun awaitAnswering(timeoutSeconds: Long): Double {
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutSeconds)
        while (System.nanoTime() < deadline) {
            if (process != null && !process.isAlive) {
                error("kTCS exited with code ${process.exitValue()} before it answered")
            }
            if ((port == null || isListening(port)) && client.vehicles() != null) {
                return ((System.nanoTime() - startNanos) / NANOS_PER_SECOND).also { readySeconds = it }
            }
            Thread.sleep(READY_POLL_MILLIS)
        }
        error("kTCS's web API did not answer within $timeoutSeconds s")
    }

    private fun isListening(port: Int): Boolean {
        val hexPort = ":%04X".format(port)
        return listOf("/proc/net/tcp", "/proc/net/tcp6").any { table ->
            runCatching { File(table).readLines() }.getOrDefault(emptyList()).drop(1).any { line ->
                val fields = line.trim().split(Regex("\\s+"))
                fields.getOrNull(1)?.endsWith(hexPort) == true && fields.getOrNull(3) == LISTEN
            }
        }
    }

    override fun close() {
        process ?: return
        process.destroy()
        if (!process.waitFor(STOP_SECONDS, TimeUnit.SECONDS)) process.destroyForcibly().waitFor()
        dataDirectory?.toFile()?.deleteRecursively()
    }

    companion object {
        private const val NANOS_PER_SECOND = 1e9
        private const val READY_POLL_MILLIS = 5L
        private const val STOP_SECONDS = 10L

        /** Connects to a kTCS that runs already; [pid], if known, lets the bench read its CPU and memory. */
        fun connect(url: String, pid: Long?): KtcsUnderTest =
            KtcsUnderTest(
                BenchClient(
                    url.trimEnd('/').let {
                        if (it.endsWith("/v1")) it else "$it/v1"
                    },
                ),
                null,
                pid,
                System.nanoTime(),
            )

        /**
         * Starts [launcher] (`ktcs`) with [model] (or its demo plant), on [port], with loopback vehicles at [timeFactor]
         * and finished orders kept for the whole run, keeping its data in a temporary directory deleted when it is
         * closed; its output goes to [log].
         */
        fun start(
            launcher: Path,
            model: Path?,
            port: Int,
            timeFactor: Double,
            log: File,
            extraSettings: List<String>,
        ): KtcsUnderTest {
            val dataDirectory = Files.createTempDirectory("ktcs-bench-data-")
            val settings = listOf(
                "kernel.dataDirectory=$dataDirectory",
                "web.port=$port",
                "web.bindAddress=127.0.0.1",
                "xml.orders.port=0",
                "xml.status.port=0",
                "xml.bindAddress=127.0.0.1",
                "loopback.timeFactor=$timeFactor",
                "orderpool.sweepAge=$DAY_MILLIS",
                // The batch workload follows every event; a burst of orders must not make kTCS drop some for it.
                "web.webSocketBufferSize=$WEB_SOCKET_BUFFER",
                // Figures stay those of the kernel alone unless a benchmark asks for the store (extraSettings win).
                "persistence.durability=OFF",
            ) + extraSettings
            val command = buildList {
                add(launcher.toString())
                add("--no-build")
                model?.let { addAll(listOf("--model", it.toString())) }
                settings.forEach { addAll(listOf("--set", it)) }
            }
            val startNanos = System.nanoTime()
            val process = ProcessBuilder(command)
                .redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log))
                .start()
            // The launcher execs java, so the child's id is the kernel's.
            val client = BenchClient("http://127.0.0.1:$port/v1")
            return KtcsUnderTest(client, process, process.pid(), startNanos, port, dataDirectory)
        }

        private const val DAY_MILLIS = 86_400_000L
        private const val LISTEN = "0A"
        private const val WEB_SOCKET_BUFFER = 1_000_000
    }
}
