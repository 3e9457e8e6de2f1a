package org.ktcs.e2e

import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.concurrent.thread
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * `./ktcs` started as a user starts it (without the build step: the test runs inside the build, after packaging).
 * Collects the merged output line by line.
 */
class KtcsProcess(vararg args: String, workingDirectory: Path = RepositoryRoot.path) : AutoCloseable {
    private val dataDirectory: Path = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-e2e-data")
    private val process: Process =
        ProcessBuilder(listOf(RepositoryRoot.path.resolve("ktcs").toString(), "--no-build") + args)
            .directory(workingDirectory.toFile())
            .redirectErrorStream(true)
            .also { it.environment().keys.removeIf { key -> key.startsWith("KTCS_") } }
            // Nothing kept between tests, nor in the repository's data/ (state store, log files), unless a test
            // asks for it with --set.
            .also {
                it.environment()["KTCS_PERSISTENCE_DURABILITY"] = "OFF"
                it.environment()["KTCS_KERNEL_DATADIRECTORY"] = dataDirectory.toString()
            }
            .start()
    private val lines = LinkedBlockingQueue<String>()
    private val seen = mutableListOf<String>()
    private val reader = thread(name = "ktcs-output", isDaemon = true) {
        try {
            process.inputStream.bufferedReader().useLines { it.forEach(lines::put) }
        } catch (_: IOException) {
            // close() killed the process while its output was being read: nothing more to read.
        }
    }

    /** Waits for a line containing [text] and returns it; fails with everything seen so far on time-out. */
    fun awaitLine(text: String, timeout: Duration = 60.seconds): String {
        val deadline = System.nanoTime() + timeout.inWholeNanoseconds
        while (System.nanoTime() < deadline) {
            val line = lines.poll(100, TimeUnit.MILLISECONDS) ?: continue
            seen += line
            if (text in line) return line
        }
        error("no line containing '$text' within $timeout; output so far:\n${output()}")
    }

    /** The process id (the JVM's: the launcher replaces itself with it). */
    val pid: Long get() = process.pid()

    /** Sends SIGTERM and returns the exit code. */
    fun terminate(): Int {
        process.destroy()
        return awaitExit()
    }

    fun awaitExit(timeout: Duration = 30.seconds): Int {
        check(process.waitFor(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS)) {
            "ktcs did not exit; output:\n${output()}"
        }
        reader.join(5_000)
        return process.exitValue()
    }

    /** Everything printed so far. */
    fun output(): String {
        lines.drainTo(seen)
        return seen.joinToString("\n")
    }

    /** Kills the process at once (SIGKILL, as `kill -9`): no shutdown hook runs. */
    fun kill() {
        process.destroyForcibly()
        process.waitFor(30, TimeUnit.SECONDS)
    }

    override fun close() {
        process.destroyForcibly()
        process.waitFor(30, TimeUnit.SECONDS)
        dataDirectory.toFile().deleteRecursively()
    }
}
