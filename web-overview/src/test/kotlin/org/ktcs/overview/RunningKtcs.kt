package org.ktcs.overview

import org.ktcs.adapters.loopback.LoopbackExtension
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.LoadedModel
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.persistence.PublishedModelFile
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path

/**
 * The real kernel application with loopback vehicles and the overview, in-process on a free port. It keeps its data
 * (the published plant model) in [dataDirectory] (a new temporary directory unless given) and, like `./ktcs`,
 * starts with the model published there, else the demo plant.
 */
class RunningKtcs(
    overrides: List<String> = emptyList(),
    model: LoadedModel? = null,
    val dataDirectory: Path = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-overview-data").also {
        it.toFile().deleteOnExit()
    },
) : AutoCloseable {
    private val config =
        ConfigLoader().load(null, emptyMap(), BASE_SETTINGS + "kernel.dataDirectory=$dataDirectory" + overrides)
    private val model = model ?: PlantModelLoader.loadAtStart(null, PublishedModelFile(dataDirectory))
    private val application = KernelApplication(config, this.model, listOf(LoopbackExtension(), OverviewExtension()))
    private val http = HttpClient.newHttpClient()

    /** E.g. `http://127.0.0.1:41234`. */
    val baseUrl: String = WEB_ADDRESS.find(application.start())?.groupValues?.get(1)
        ?: error("the ready line names no web API address")

    fun get(path: String): HttpResponse<String> = send(HttpRequest.newBuilder(uri(path)).GET())

    fun post(path: String, json: String): HttpResponse<String> = send(
        HttpRequest.newBuilder(uri(path)).header("Content-Type", "application/json")
            .POST(HttpRequest.BodyPublishers.ofString(json)),
    )

    fun put(path: String, json: String = ""): HttpResponse<String> = send(
        HttpRequest.newBuilder(uri(path)).header("Content-Type", "application/json")
            .PUT(HttpRequest.BodyPublishers.ofString(json)),
    )

    private fun uri(path: String) = URI.create(baseUrl + path)

    private fun send(request: HttpRequest.Builder): HttpResponse<String> =
        http.send(request.build(), HttpResponse.BodyHandlers.ofString())

    override fun close() = application.stop()

    private companion object {
        val WEB_ADDRESS = Regex("""web API (http://\S+)/v1""")

        // Fast simulated vehicles, so orders finish within seconds.
        val BASE_SETTINGS = listOf(
            "web.bindAddress=127.0.0.1",
            "web.port=0",
            "loopback.timeFactor=10",
            "loopback.operatingTime=2000",
            "log.level=WARN",
        )
    }
}
