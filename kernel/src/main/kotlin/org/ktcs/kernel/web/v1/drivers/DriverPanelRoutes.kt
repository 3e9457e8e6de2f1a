package org.ktcs.kernel.web.v1.drivers

import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.post
import io.ktor.server.routing.route
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.pathName
import org.ktcs.kernel.web.v1.receiveJson
import org.ktcs.kernel.web.v1.required

/**
 * kTCS's driver panel routes: `GET /vehicles/{NAME}/driverPanel` (the driver, its panel, state and command queue),
 * `POST /vehicles/{NAME}/driverCommand` (a command checked against the driver's panel) and
 * `GET /vehicles/{NAME}/driverEvents` (the latest events the driver published).
 */
fun Route.driverPanelRoutes(services: KernelServices) = route("/vehicles/{NAME}") {
    get("/driverPanel") { call.respond(services.vehicles.driverPanel(call.pathName()).toDto()) }
    post("/driverCommand") {
        val request = call.receiveJson<PostDriverCommandRequest>()
        services.vehicles.executeDriverCommand(
            call.pathName(),
            request.driver.required("driver"),
            request.command.required("command"),
            request.parameters,
        )
        call.respond(HttpStatusCode.OK)
    }
    get("/driverEvents") {
        call.respond(services.vehicles.recentDriverEvents(call.pathName()).map { it.toDto() })
    }
}
