package org.ktcs.kernel.web.v1.vehicles

import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.post
import io.ktor.server.routing.put
import io.ktor.server.routing.route
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.booleanQuery
import org.ktcs.kernel.web.v1.dispatcherTrigger
import org.ktcs.kernel.web.v1.parseEnum
import org.ktcs.kernel.web.v1.pathName
import org.ktcs.kernel.web.v1.receiveJson
import org.ktcs.kernel.web.v1.requiredBooleanQuery
import org.ktcs.kernel.web.v1.requiredQuery

/** `/vehicles`: read vehicles and change what openTCS's web API v1 lets clients change. */
fun Route.vehicleRoutes(services: KernelServices) = route("/vehicles") {
    get {
        val procState = call.request.queryParameters["procState"]?.let { parseEnum<ProcState>(it, "procState") }
        call.respond(services.vehicles.vehicles(procState).map { it.toDto() })
    }
    dispatcherTrigger(services)
    route("/{NAME}") {
        get {
            val name = call.pathName()
            call.respond(
                (services.vehicles.vehicle(name) ?: throw ObjectUnknownException("unknown vehicle '$name'")).toDto(),
            )
        }
        post("/withdrawal") {
            services.dispatcher.withdrawByVehicle(
                call.pathName(),
                call.booleanQuery("immediate"),
                call.booleanQuery("disableVehicle"),
            )
            call.respond(HttpStatusCode.OK)
        }
        post("/rerouteRequest") {
            services.dispatcher.reroute(call.pathName(), call.booleanQuery("forced"))
            call.respond(HttpStatusCode.OK)
        }
        put("/integrationLevel") {
            services.vehicles.setIntegrationLevel(
                call.pathName(),
                parseEnum<IntegrationLevel>(call.requiredQuery("newValue"), "newValue"),
            )
            call.respond(HttpStatusCode.OK)
        }
        put("/paused") {
            services.vehicles.setPaused(call.pathName(), call.requiredBooleanQuery("newValue"))
            call.respond(HttpStatusCode.OK)
        }
        put("/allowedOrderTypes") {
            services.vehicles.setAllowedOrderTypes(
                call.pathName(),
                call.receiveJson<PutAllowedOrderTypesRequest>().toDomain(),
            )
            call.respond(HttpStatusCode.OK)
        }
        put("/acceptableOrderTypes") {
            services.vehicles.setAcceptableOrderTypes(
                call.pathName(),
                call.receiveJson<PutAcceptableOrderTypesRequest>().toDomain(),
            )
            call.respond(HttpStatusCode.OK)
        }
        put("/energyLevelThresholdSet") {
            services.vehicles.setEnergyLevelThresholdSet(
                call.pathName(),
                call.receiveJson<PutEnergyLevelThresholdSetRequest>().toDomain(),
            )
            call.respond(HttpStatusCode.OK)
        }
        put("/envelopeKey") {
            services.vehicles.setEnvelopeKey(
                call.pathName(),
                call.request.queryParameters["newValue"]?.ifEmpty {
                    null
                },
            )
            call.respond(HttpStatusCode.OK)
        }
        post("/routeComputationQuery") {
            val query = call.receiveJson<PostRouteComputationRequest>().toDomain()
            val maxRoutes = call.request.queryParameters["maxRoutesPerDestinationPoint"]?.let { raw ->
                raw.toIntOrNull()?.takeIf { it >= 1 }
                    ?: throw org.ktcs.api.error.InvalidRequestException(
                        "maxRoutesPerDestinationPoint must be a positive number, was '$raw'",
                    )
            } ?: 1
            val routes = services.router.computeRoutes(
                call.pathName(),
                query.sourcePoint,
                query.destinationPoints,
                query.resourcesToAvoid,
                maxRoutes,
            )
            call.respond(routes.toRouteComputationResponse())
        }
        commAdapterRoutes(services)
    }
}

private fun Route.commAdapterRoutes(services: KernelServices) = route("/commAdapter") {
    get("/attachmentInformation") { call.respond(services.vehicles.driverAttachment(call.pathName()).toDto()) }
    put("/attachment") {
        services.vehicles.attachDriver(call.pathName(), call.requiredQuery("newValue"))
        call.respond(HttpStatusCode.OK)
    }
    put("/enabled") {
        services.vehicles.setDriverEnabled(call.pathName(), call.requiredBooleanQuery("newValue"))
        call.respond(HttpStatusCode.OK)
    }
    post("/message") {
        services.vehicles.sendDriverMessage(
            call.pathName(),
            call.receiveJson<PostCommAdapterMessageRequest>().toDomain(),
        )
        call.respond(HttpStatusCode.OK)
    }
}
