package org.ktcs.kernel.web.v1.events

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeSameInstanceAs
import io.kotest.matchers.types.shouldNotBeSameInstanceAs
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonNull
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.orders.RouteDto
import org.ktcs.kernel.web.v1.orders.toDto

class EncodedRoutesTest : FunSpec({
    val route = Route(listOf(Step("A--B", "A", "B"), Step("B--C", "B", "C", routeIndex = 1)), costs = 4000)

    test("a route is encoded once while its drive order keeps it, and anew once the drive order gets another") {
        val first = EncodedRoutes.of("order-1/drive-1", route)

        EncodedRoutes.of("order-1/drive-1", route) shouldBeSameInstanceAs first
        val rerouted = route.copy(steps = route.steps.take(1))
        val second = EncodedRoutes.of("order-1/drive-1", rerouted)
        second shouldNotBeSameInstanceAs first
        Json.parseToJsonElement(second.toString()) shouldBe
            Json.parseToJsonElement(V1Json.json.encodeToString(RouteDto.serializer(), rerouted.toDto()))
    }

    test("an order's event carries the route as RouteDto writes it, in events and in snapshots alike") {
        val written = V1Json.json.encodeToString(SseDriveOrderDto.serializer(), dto())
        val inTree = V1Json.json.encodeToString(V1Json.json.encodeToJsonElement(SseDriveOrderDto.serializer(), dto()))
        val expected = Json.parseToJsonElement(V1Json.json.encodeToString(RouteDto.serializer(), route.toDto()))

        Json.parseToJsonElement(written).jsonObjectField("route") shouldBe expected
        Json.parseToJsonElement(inTree).jsonObjectField("route") shouldBe expected
        val withoutRoute = V1Json.json.encodeToString(SseDriveOrderDto.serializer(), dto(route = null))
        Json.parseToJsonElement(withoutRoute).jsonObjectField("route") shouldBe JsonNull
    }
}) {
    private companion object {
        fun dto(route: Route? = Route(listOf(Step("A--B", "A", "B"), Step("B--C", "B", "C", routeIndex = 1)), 4000)) =
            SseDriveOrderDto(
                name = "drive-1",
                destination = SseDestinationDto("C", "Unload cargo", emptyMap()),
                transportOrder = "order-2",
                route = EncodedRoutes.of("order-2/drive-1", route),
                state = "TRAVELLING",
            )

        fun kotlinx.serialization.json.JsonElement.jsonObjectField(name: String) =
            (this as kotlinx.serialization.json.JsonObject).getValue(name)
    }
}
