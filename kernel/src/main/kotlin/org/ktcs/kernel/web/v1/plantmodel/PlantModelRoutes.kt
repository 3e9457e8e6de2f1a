package org.ktcs.kernel.web.v1.plantmodel

import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.put
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.booleanQuery
import org.ktcs.kernel.web.v1.pathName
import org.ktcs.kernel.web.v1.requiredQuery

/** The plant model and the locks on paths and locations. */
fun Route.plantModelRoutes(services: KernelServices) {
    get("/plantModel") { call.respond(services.plantModel.plantModel().toDto()) }
    put("/paths/{NAME}/locked") {
        call.requiredQuery("newValue")
        services.plantModel.setPathLocked(call.pathName(), call.booleanQuery("newValue"))
        call.respond(HttpStatusCode.OK)
    }
    put("/locations/{NAME}/locked") {
        call.requiredQuery("newValue")
        services.plantModel.setLocationLocked(call.pathName(), call.booleanQuery("newValue"))
        call.respond(HttpStatusCode.OK)
    }
}
