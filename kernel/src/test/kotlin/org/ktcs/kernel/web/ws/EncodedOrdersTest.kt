package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
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
        )

        val spliced = EncodedOrders.utf8(order).decodeToString()

        Json.parseToJsonElement(spliced) shouldBe
            Json.parseToJsonElement(V1Json.json.encodeToString(SseTransportOrderDto.serializer(), order.toSseDto()))
    }
})
