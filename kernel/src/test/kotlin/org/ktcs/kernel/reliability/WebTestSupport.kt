package org.ktcs.kernel.reliability

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriverFactory
import org.slf4j.LoggerFactory
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.net.http.WebSocket
import java.nio.file.Files
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CompletionStage

private val stepVehicles = object : KtcsExtension {
    override val name = "step-vehicles"

    override fun module(): Module = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
}

/** A kernel with the demo plant and its web API on 127.0.0.1, and the base URL of its `/v1`. */
fun startKernel(vararg settings: String): Pair<KernelApplication, String> {
    // A published plant model goes to a directory of its own, not the working directory's data/.
    val data = Files.createTempDirectory("ktcs-data").toFile().apply { deleteOnExit() }
    val settingsForTest = listOf("web.bindAddress=127.0.0.1", "web.port=0", "kernel.dataDirectory=$data")
    val config = ConfigLoader().load(null, emptyMap(), settingsForTest + settings)
    val application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(stepVehicles)) {}
    val base = Regex("web API (http://\\S+/v1)").find(application.start())!!.groupValues[1]
    return application to base
}

suspend fun withKernel(vararg settings: String, block: suspend (String) -> Unit) {
    val (application, base) = startKernel(*settings)
    try {
        block(base)
    } finally {
        application.stop()
    }
}

fun send(
    http: HttpClient,
    method: String,
    url: String,
    body: String? = null,
    json: Boolean = false,
    headers: Map<String, String> = emptyMap(),
): HttpResponse<String> {
    val publisher = body?.let(HttpRequest.BodyPublishers::ofString) ?: HttpRequest.BodyPublishers.noBody()
    val request = HttpRequest.newBuilder(URI(url)).method(method, publisher)
    if (json) request.header("Content-Type", "application/json")
    headers.forEach { (name, value) -> request.header(name, value) }
    return http.send(request.build(), HttpResponse.BodyHandlers.ofString())
}

/** ERROR lines any logger writes while [block] runs. */
suspend fun errorsLoggedWhile(block: suspend () -> Unit): List<String> {
    val root = LoggerFactory.getLogger(Logger.ROOT_LOGGER_NAME) as Logger
    val appender = ListAppender<ILoggingEvent>().apply { start() }
    root.addAppender(appender)
    try {
        block()
    } finally {
        root.detachAppender(appender)
    }
    return appender.list.filter { it.level == Level.ERROR }.map { "${it.loggerName}: ${it.formattedMessage}" }
}

/** A WebSocket listener that records text messages and the close code (or -1 when the connection failed). */
class RecordingWebSocket : WebSocket.Listener {
    val messages = java.util.concurrent.LinkedBlockingQueue<String>()
    val closed = CompletableFuture<Int>()

    override fun onText(webSocket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
        messages.put(data.toString())
        webSocket.request(1)
        return null
    }

    override fun onClose(webSocket: WebSocket, statusCode: Int, reason: String): CompletionStage<*>? {
        closed.complete(statusCode)
        return null
    }

    override fun onError(webSocket: WebSocket, error: Throwable) {
        closed.complete(-1)
    }
}
