package org.ktcs.kernel.web.v1

import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.post
import org.ktcs.api.service.KernelServices

/**
 * `POST dispatcher/trigger` below this route: runs the dispatcher. openTCS's web API offers it under `/transportOrders`
 * and `/vehicles`, and kTCS also at the top.
 */
fun Route.dispatcherTrigger(services: KernelServices) {
    post("/dispatcher/trigger") {
        services.dispatcher.dispatch()
        call.respond(HttpStatusCode.OK)
    }
}
