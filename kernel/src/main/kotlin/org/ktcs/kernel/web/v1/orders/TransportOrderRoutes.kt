package org.ktcs.kernel.web.v1.orders

import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.response.respondBytes
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.post
import io.ktor.server.routing.put
import io.ktor.server.routing.route
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.booleanQuery
import org.ktcs.kernel.web.v1.dispatcherTrigger
import org.ktcs.kernel.web.v1.pathName
import org.ktcs.kernel.web.v1.receiveJson

/**
 * `/transportOrders`: list, read, create, withdraw, assign now, change the intended vehicle. Orders are written from
 * [json], which encodes each order version once.
 */
fun Route.transportOrderRoutes(services: KernelServices, json: TransportOrderJson = TransportOrderJson()) = route(
    "/transportOrders",
) {
    get {
        val vehicle = services.knownVehicle(call.request.queryParameters["intendedVehicle"])
        val orders = services.transportOrders.transportOrders(vehicle)
        call.respond(json.list(orders, wholePool = vehicle == null))
    }
    dispatcherTrigger(services)
    route("/{NAME}") {
        get {
            val name = call.pathName()
            val order =
                services.transportOrders.transportOrder(name)
                    ?: throw ObjectUnknownException("unknown transport order '$name'")
            call.respondBytes(json.of(order), JSON_UTF8)
        }
        post {
            val request = call.receiveJson(PostTransportOrderRequest.serializer())
            val created = services.transportOrders.createTransportOrder(request.toDomain(call.pathName()))
            call.respondBytes(json.of(created), JSON_UTF8)
        }
        post("/withdrawal") {
            services.dispatcher.withdrawByTransportOrder(
                call.pathName(),
                call.booleanQuery("immediate"),
                call.booleanQuery("disableVehicle"),
            )
            call.respond(HttpStatusCode.OK)
        }
        post("/immediateAssignment") {
            services.dispatcher.assignNow(call.pathName())
            call.respond(HttpStatusCode.OK)
        }
        put("/intendedVehicle") {
            services.transportOrders.setIntendedVehicle(
                call.pathName(),
                call.request.queryParameters["vehicle"]?.ifEmpty {
                    null
                },
            )
            call.respond(HttpStatusCode.OK)
        }
    }
}

/** `/orderSequences`: list, read, create, mark complete. */
fun Route.orderSequenceRoutes(services: KernelServices) = route("/orderSequences") {
    get {
        val vehicle = services.knownVehicle(call.request.queryParameters["intendedVehicle"])
        call.respond(services.transportOrders.orderSequences(vehicle).map { it.toDto() })
    }
    route("/{NAME}") {
        get {
            val name = call.pathName()
            val sequence =
                services.transportOrders.orderSequence(name)
                    ?: throw ObjectUnknownException("unknown order sequence '$name'")
            call.respond(sequence.toDto())
        }
        post {
            val request = call.receiveJson<PostOrderSequenceRequest>()
            call.respond(services.transportOrders.createOrderSequence(request.toDomain(call.pathName())).toDto())
        }
        put("/complete") {
            services.transportOrders.markOrderSequenceComplete(call.pathName())
            call.respond(HttpStatusCode.OK)
        }
    }
}

/** [name] if it is `null` or names a vehicle; an unknown vehicle is a 404, as in openTCS's filters. */
private suspend fun KernelServices.knownVehicle(name: String?): String? {
    name?.let { vehicles.vehicle(it) ?: throw ObjectUnknownException("unknown vehicle '$it'") }
    return name
}
