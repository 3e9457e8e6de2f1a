package org.ktcs.kernel.web

import io.ktor.http.HttpStatusCode
import io.ktor.server.plugins.origin
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.delete
import io.ktor.server.routing.get
import kotlinx.serialization.Serializable
import org.ktcs.kernel.web.plugins.respondErrors

/**
 * `GET /v1/kernel/version`, and `DELETE /v1/kernel`, which shuts kTCS down when asked from this machine only, and
 * only with the access key (checked by [org.ktcs.kernel.web.plugins.AccessKey] before this runs) or with
 * `web.allowLocalShutdown`: any program on the machine, a browser tab included, can reach 127.0.0.1.
 */
fun Route.kernelRoutes(version: KernelVersion, shutdown: ShutdownRequest, options: WebOptions = WebOptions()) {
    get("/kernel/version") { call.respond(version.toDto()) }
    delete("/kernel") {
        if (call.request.origin.remoteAddress !in LOCAL_ADDRESSES) {
            call.respondErrors(HttpStatusCode.Forbidden, "the kernel can only be shut down from the machine it runs on")
            return@delete
        }
        if (options.accessKey.isEmpty() && !options.allowLocalShutdown) {
            call.respondErrors(
                HttpStatusCode.Forbidden,
                "shutting kTCS down over the web API needs web.accessKey (sent as X-Api-Access-Key) or " +
                    "web.allowLocalShutdown=true",
            )
            return@delete
        }
        call.respond(HttpStatusCode.OK)
        shutdown.request()
    }
}

private val LOCAL_ADDRESSES = setOf("127.0.0.1", "0:0:0:0:0:0:0:1", "::1", "localhost")

@Serializable
data class KernelVersionDto(
    val baselineVersion: String,
    val customizationName: String,
    val customizationVersion: String,
)

private fun KernelVersion.toDto() = KernelVersionDto(
    baselineVersion = version,
    customizationName = "kTCS",
    customizationVersion = version,
)
