package org.ktcs.examples.clients

import io.ktor.client.HttpClient
import io.ktor.client.call.body
import io.ktor.client.engine.cio.CIO
import io.ktor.client.plugins.contentnegotiation.ContentNegotiation
import io.ktor.client.plugins.defaultRequest
import io.ktor.client.plugins.websocket.WebSockets
import io.ktor.client.plugins.websocket.webSocket
import io.ktor.client.request.get
import io.ktor.client.request.header
import io.ktor.client.request.parameter
import io.ktor.client.request.post
import io.ktor.client.request.put
import io.ktor.client.request.setBody
import io.ktor.http.ContentType
import io.ktor.http.contentType
import io.ktor.serialization.kotlinx.json.json
import io.ktor.websocket.Frame
import io.ktor.websocket.readText
import kotlinx.coroutines.channels.ProducerScope
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.channelFlow
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject

/**
 * A kTCS client written with the Ktor client: transport orders, order sequences, withdrawals and the live event
 * stream of the WebSocket. [baseUrl] is the web API without `/v1`, e.g. `http://localhost:55200`; [accessKey] is
 * needed when kTCS has `web.accessKey` set. Non-2xx answers throw, with kTCS's error messages in the body.
 */
class KtcsClient(private val baseUrl: String, accessKey: String? = null) : AutoCloseable {
    // snippet:client-setup
    private val json = Json { ignoreUnknownKeys = true }
    private val http = HttpClient(CIO) {
        expectSuccess = true
        install(ContentNegotiation) { json(json) }
        install(WebSockets)
        defaultRequest {
            url("$baseUrl/v1/")
            accessKey?.let { header("X-Api-Access-Key", it) }
        }
    }
    // end-snippet

    // snippet:create-order-to-location

    /** Creates an order that performs [operation] at [location], e.g. "Load cargo" at "Storage 01". */
    suspend fun createOrderToLocation(name: String, location: String, operation: String): TransportOrderView =
        http.post("transportOrders/$name") {
            contentType(ContentType.Application.Json)
            setBody(TransportOrderRequest(listOf(DestinationRequest(location, operation))))
        }.body()
    // end-snippet

    // snippet:create-order-to-point

    /** Creates an order that sends a vehicle (any, or [vehicle]) to [point]. */
    suspend fun createOrderToPoint(name: String, point: String, vehicle: String? = null): TransportOrderView =
        http.post("transportOrders/$name") {
            contentType(ContentType.Application.Json)
            setBody(TransportOrderRequest(listOf(DestinationRequest(point, "MOVE")), intendedVehicle = vehicle))
        }.body()
    // end-snippet

    // snippet:order-sequence

    /**
     * Creates an order sequence and its orders, one per (location, operation) step, and marks it complete: one
     * vehicle carries them out one after the other, in this order.
     */
    suspend fun createOrderSequence(name: String, steps: List<Pair<String, String>>): List<TransportOrderView> {
        http.post("orderSequences/$name") {
            contentType(ContentType.Application.Json)
            setBody(OrderSequenceRequest(failureFatal = true))
        }
        val orders = steps.mapIndexed { index, (location, operation) ->
            http.post("transportOrders/$name-${index + 1}") {
                contentType(ContentType.Application.Json)
                setBody(TransportOrderRequest(listOf(DestinationRequest(location, operation)), wrappingSequence = name))
            }.body<TransportOrderView>()
        }
        http.put("orderSequences/$name/complete")
        return orders
    }
    // end-snippet

    // snippet:withdraw-order

    /** Withdraws an order: regularly (the vehicle finishes what it was sent) or [immediate]ly. */
    suspend fun withdrawOrder(name: String, immediate: Boolean = false) {
        http.post("transportOrders/$name/withdrawal") { parameter("immediate", immediate) }
    }
    // end-snippet

    // snippet:withdraw-by-vehicle

    /** Withdraws whatever [vehicle] is doing; [disableVehicle] also takes it out of dispatching. */
    suspend fun withdrawByVehicle(vehicle: String, immediate: Boolean = false, disableVehicle: Boolean = false) {
        http.post("vehicles/$vehicle/withdrawal") {
            parameter("immediate", immediate)
            parameter("disableVehicle", disableVehicle)
        }
    }
    // end-snippet

    suspend fun transportOrder(name: String): TransportOrderView = http.get("transportOrders/$name").body()

    suspend fun vehicle(name: String): VehicleView = http.get("vehicles/$name").body()

    // snippet:subscribe-events

    /**
     * The WebSocket's messages for [topics] (e.g. "transportOrders", "vehicles"): a snapshot per topic, then every
     * change as an event with `previous` and `current`. Collecting the flow opens the connection; cancelling the
     * collector closes it.
     */
    fun events(vararg topics: String): Flow<JsonObject> = channelFlow {
        http.webSocket("${baseUrl.replaceFirst("http", "ws")}/v1/ws") {
            send(Frame.Text(json.encodeToString(Subscription.serializer(), Subscription("subscribe", topics.toList()))))
            for (frame in incoming) {
                if (frame is Frame.Text) sendMessage(json.parseToJsonElement(frame.readText()).jsonObject)
            }
        }
    }
    // end-snippet

    private suspend fun ProducerScope<JsonObject>.sendMessage(message: JsonObject) = send(message)

    override fun close() = http.close()
}
