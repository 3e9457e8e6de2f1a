package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.SseTransportOrderDto
import org.ktcs.kernel.web.v1.events.toSseDto
import java.time.Instant

class EncodedOrdersTest : FunSpec({
    test(
        "an order with its routes spliced in as bytes is the JSON the serializer writes, characters beyond ASCII too",
    ) {
        val route = Route(listOf(Step("Ä--Ö", "Ä", "Ö"), Step("Ö--→", "Ö", "→", routeIndex = 1)), costs = 4000)
        val order = TransportOrder(
            name = "Auftrag-ü",
            driveOrders = listOf(
                DriveOrder("laden", Destination("Station-Ä", "Load cargo"), route),
                DriveOrder("entladen", Destination("Station-→", "Unload cargo")),
                DriveOrder("zurück", Destination("Park-ß", "NOP"), route.copy(costs = 1)),
            ),
            properties = mapOf("Kunde" to "Müller \u0001"),
            creationTime = Instant.EPOCH,
            history = listOf(
                HistoryEntry(Instant.EPOCH, "erstellt", "über \"API\""),
                HistoryEntry(Instant.MAX, "fertig"),
            ),
        )

        val spliced = EncodedOrders.utf8(order).decodeToString()

        Json.parseToJsonElement(spliced) shouldBe
            Json.parseToJsonElement(V1Json.json.encodeToString(SseTransportOrderDto.serializer(), order.toSseDto()))
    }

    test("an order's history goes in only where it is sent, and as it is now after it changed") {
        val order = TransportOrder(
            name = "T1",
            driveOrders = listOf(DriveOrder("D1", Destination("L1", "Load cargo"))),
            creationTime = Instant.EPOCH,
            history = listOf(HistoryEntry(Instant.EPOCH, "created")),
        )
        val advanced = order.copy(currentRouteStepIndex = 2, history = order.history + HistoryEntry(Instant.EPOCH, "x"))
        fun serialized(order: TransportOrder) = Json.parseToJsonElement(
            V1Json.json.encodeToString(SseTransportOrderDto.serializer(), order.toSseDto()),
        ).jsonObject

        val first = EncodedOrders.marked(order)
        val second = EncodedOrders.marked(advanced)

        Json.parseToJsonElement(first.full.decodeToString()) shouldBe serialized(order)
        Json.parseToJsonElement(second.full.decodeToString()) shouldBe serialized(advanced)
        second.without(listOf("history")).decodeToString() shouldNotContain "created"
        Json.parseToJsonElement(second.without(listOf("history")).decodeToString()) shouldBe
            JsonObject(serialized(advanced) - "history")
    }

    test("an order without some fields is cut from the marked text: its routes go in only with its drive orders") {
        val route = Route(listOf(Step("A--B", "A", "B"), Step("B--C", "B", "C", routeIndex = 1)), costs = 4000)
        val order = TransportOrder(
            name = "T1",
            driveOrders = listOf(DriveOrder("D1", Destination("L1", "Load cargo"), route)),
            properties = mapOf("k" to "v"),
            creationTime = Instant.EPOCH,
        )
        val whole = Json.parseToJsonElement(EncodedOrders.utf8(order).decodeToString()).jsonObject
        val marked = EncodedOrders.marked(order)

        val withRoutes = Json.parseToJsonElement(marked.without(listOf("properties")).decodeToString()).jsonObject
        val withoutRoutes = marked.without(listOf("driveOrders", "properties")).decodeToString()

        withRoutes shouldBe JsonObject(whole - "properties")
        Json.parseToJsonElement(withoutRoutes) shouldBe JsonObject(whole - "properties" - "driveOrders")
        withoutRoutes shouldNotContain "A--B"
    }
})
