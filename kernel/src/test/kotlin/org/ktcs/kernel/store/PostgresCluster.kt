package org.ktcs.kernel.store

import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit

/**
 * A throw-away PostgreSQL cluster for a test: Debian's server binaries (package `postgresql`), initdb into a temporary
 * directory, started on [port] for 127.0.0.1 only, with trust authentication. As root it runs as the `postgres` user
 * (PostgreSQL refuses to run as root). [start] returns `null` with the reason when the binaries are missing, unless
 * `KTCS_REQUIRE_POSTGRES=1`, which makes that an error.
 */
class PostgresCluster private constructor(private val bin: Path, private val directory: Path, val port: Int) :
    AutoCloseable {
    val url = "jdbc:postgresql://127.0.0.1:$port/postgres"
    val user = "ktcs"

    override fun close() {
        run(
            listOf(
                bin.resolve("pg_ctl").toString(),
                "-D",
                directory.resolve("data").toString(),
                "-m",
                "immediate",
                "-w",
                "stop",
            ),
        )
        directory.toFile().deleteRecursively()
    }

    private fun run(command: List<String>) {
        val asPostgres = if (isRoot()) listOf("runuser", "-u", "postgres", "--") + command else command
        val process = ProcessBuilder(asPostgres).redirectErrorStream(true).start()
        val output = process.inputStream.bufferedReader().readText()
        check(process.waitFor(60, TimeUnit.SECONDS) && process.exitValue() == 0) {
            "${command.joinToString(" ")} failed:\n$output"
        }
    }

    companion object {
        fun start(port: Int): PostgresCluster? {
            val bin = binaries()
            if (bin == null) {
                val reason = "PostgreSQL server binaries not found (install Debian's postgresql package)"
                check(System.getenv("KTCS_REQUIRE_POSTGRES") != "1") { "$reason, and KTCS_REQUIRE_POSTGRES=1" }
                println("SKIPPED PostgreSQL tests: $reason")
                return null
            }
            val directory = Files.createTempDirectory("ktcs-postgres")
            if (isRoot()) ProcessBuilder("chown", "postgres", directory.toString()).start().waitFor()
            val cluster = PostgresCluster(bin, directory, port)
            val data = directory.resolve("data").toString()
            cluster.run(
                listOf(bin.resolve("initdb").toString(), "-D", data, "-U", "ktcs", "--auth=trust", "-E", "UTF8"),
            )
            cluster.run(
                listOf(
                    bin.resolve("pg_ctl").toString(), "-D", data, "-w", "-l", directory.resolve("log").toString(),
                    "-o", "-p $port -k $directory -c listen_addresses=127.0.0.1 -c fsync=off", "start",
                ),
            )
            return cluster
        }

        private fun binaries(): Path? = File("/usr/lib/postgresql").listFiles().orEmpty()
            .sortedByDescending { it.name.toIntOrNull() ?: 0 }
            .map { it.toPath().resolve("bin") }
            .firstOrNull { Files.isExecutable(it.resolve("initdb")) && Files.isExecutable(it.resolve("pg_ctl")) }

        private fun isRoot() = System.getProperty("user.name") == "root"
    }
}
