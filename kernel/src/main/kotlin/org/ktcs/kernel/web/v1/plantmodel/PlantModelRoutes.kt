package org.ktcs.kernel.web.v1.plantmodel

import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.post
import io.ktor.server.routing.put
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import kotlinx.serialization.Serializable
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.model.PlantModel
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.pathName
import org.ktcs.kernel.web.v1.receiveJson
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.requiredBooleanQuery

/** The body of `POST /plantModel/topologyUpdateRequest`: the paths whose routing properties changed. */
@Serializable
data class TopologyUpdateRequest(val paths: List<String>? = null)

// The model's own types reject some values (e.g. a negative length) as they are built; those are bad input too.
internal fun PlantModelDto.toCheckedDomain(): PlantModel = try {
    toDomain()
} catch (error: IllegalArgumentException) {
    throw InvalidRequestException("invalid plant model: ${error.message}")
}

/** The plant model and the locks on paths and locations. */
fun Route.plantModelRoutes(services: KernelServices) {
    get("/plantModel") { call.respond(services.plantModel.plantModel().toDto()) }
    put("/plantModel") {
        val model = call.receiveJson<PlantModelDto>()
        // Checking a large plant takes a while; not on the web server's event loop.
        services.plantModel.replacePlantModel(withContext(Dispatchers.Default) { model.toCheckedDomain() })
        call.respond(HttpStatusCode.OK)
    }
    post("/plantModel/topologyUpdateRequest") {
        val paths = call.receiveJson<TopologyUpdateRequest>().paths.required("paths")
        val model = services.plantModel.plantModel()
        paths.firstOrNull { model.path(it) == null }?.let { throw ObjectUnknownException("unknown path '$it'") }
        services.plantModel.updateRoutingTopology()
        call.respond(HttpStatusCode.OK)
    }
    put("/paths/{NAME}/locked") {
        services.plantModel.setPathLocked(call.pathName(), call.requiredBooleanQuery("newValue"))
        call.respond(HttpStatusCode.OK)
    }
    put("/locations/{NAME}/locked") {
        services.plantModel.setLocationLocked(call.pathName(), call.requiredBooleanQuery("newValue"))
        call.respond(HttpStatusCode.OK)
    }
}
