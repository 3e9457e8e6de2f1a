package org.ktcs.adapters.vda5050

import java.net.Socket
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit

/**
 * Debian's Mosquitto, started by a test on a free port of the loopback interface with anonymous access; `null` (with
 * the reason printed) where it is not installed, unless `KTCS_REQUIRE_MOSQUITTO=1` (CI) makes that a failure.
 */
class Mosquitto private constructor(
    private val process: Process,
    val port: Int,
    private val dir: Path,
) : AutoCloseable {
    val url: String get() = "tcp://127.0.0.1:$port"

    override fun close() {
        process.destroy()
        if (!process.waitFor(5, TimeUnit.SECONDS)) process.destroyForcibly()
        dir.toFile().deleteRecursively()
    }

    companion object {
        private val BINARIES = listOf("/usr/sbin/mosquitto", "/usr/bin/mosquitto", "/usr/local/sbin/mosquitto")

        fun startOrSkip(): Mosquitto? {
            val binary = BINARIES.map(Path::of).firstOrNull(Files::isExecutable)
            if (binary == null) {
                check(System.getenv("KTCS_REQUIRE_MOSQUITTO") != "1") {
                    "KTCS_REQUIRE_MOSQUITTO=1 but mosquitto is not installed (apt-get install -y mosquitto)"
                }
                println(
                    "SKIPPED: the VDA 5050 tests against Mosquitto need Debian's mosquitto (apt-get install -y mosquitto)",
                )
                return null
            }
            val port = freePort()
            val dir = Files.createTempDirectory("ktcs-mosquitto")
            val config = dir.resolve("mosquitto.conf")
            Files.writeString(config, "listener $port 127.0.0.1\nallow_anonymous true\npersistence false\n")
            val process = ProcessBuilder(binary.toString(), "-c", config.toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("mosquitto.log").toFile()).start()
            repeat(100) {
                if (runCatching { Socket("127.0.0.1", port).close() }.isSuccess) return Mosquitto(process, port, dir)
                check(process.isAlive) { "mosquitto stopped: ${Files.readString(dir.resolve("mosquitto.log"))}" }
                Thread.sleep(50)
            }
            process.destroyForcibly()
            error("mosquitto did not listen on port $port within 5 s")
        }
    }
}
