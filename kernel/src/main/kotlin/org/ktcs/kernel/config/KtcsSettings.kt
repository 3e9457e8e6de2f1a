package org.ktcs.kernel.config

/** Every setting kTCS knows. A key that is not listed here is rejected wherever it appears. */
object KtcsSettings {
    private const val MAX_PORT = 65535

    val webBindAddress = stringSetting(
        "web.bindAddress",
        "0.0.0.0",
        "Address the web API and the browser overview listen on (0.0.0.0: all interfaces, 127.0.0.1: this machine only).",
    )
    val webPort =
        intSetting(
            "web.port",
            55200,
            0..MAX_PORT,
            "TCP port of the web API and the browser overview (0: any free port).",
        )
    val xmlOrdersPort =
        intSetting("xml.orders.port", 55555, 0..MAX_PORT, "TCP port of the XML order channel (0: any free port).")
    val xmlStatusPort =
        intSetting("xml.status.port", 44444, 0..MAX_PORT, "TCP port of the XML status channel (0: any free port).")
    val loopbackTimeFactor = positiveDoubleSetting(
        "loopback.timeFactor",
        1.0,
        "How much faster than real time the simulated loopback vehicles move (2.0: twice as fast).",
    )
    val logLevel = enumSetting(
        "log.level",
        LogLevel.INFO,
        "Log level of kTCS's own loggers: ERROR, WARN, INFO, DEBUG or TRACE. Libraries log warnings and errors only.",
    )

    val all: List<Setting<*>> =
        listOf(webBindAddress, webPort, xmlOrdersPort, xmlStatusPort, loopbackTimeFactor, logLevel)
}

/** Log levels a user can choose, in SLF4J's names. */
enum class LogLevel { ERROR, WARN, INFO, DEBUG, TRACE }
