package org.ktcs.kernel.web

import io.ktor.http.HttpStatusCode
import io.ktor.server.plugins.origin
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.delete
import io.ktor.server.routing.get
import kotlinx.serialization.Serializable
import org.ktcs.kernel.web.plugins.respondErrors

/** `GET /v1/kernel/version`, and `DELETE /v1/kernel`, which shuts kTCS down when asked from this machine only. */
fun Route.kernelRoutes(version: KernelVersion, shutdown: ShutdownRequest) {
    get("/kernel/version") { call.respond(version.toDto()) }
    delete("/kernel") {
        if (call.request.origin.remoteAddress !in LOCAL_ADDRESSES) {
            call.respondErrors(HttpStatusCode.Forbidden, "the kernel can only be shut down from the machine it runs on")
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
