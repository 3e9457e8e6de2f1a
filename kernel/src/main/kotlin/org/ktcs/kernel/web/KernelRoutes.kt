package org.ktcs.kernel.web

import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import kotlinx.serialization.Serializable

/** `GET /v1/kernel/version`, as openTCS's web API answers it. */
fun Route.kernelRoutes(version: KernelVersion) {
    get("/kernel/version") { call.respond(version.toDto()) }
}

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
