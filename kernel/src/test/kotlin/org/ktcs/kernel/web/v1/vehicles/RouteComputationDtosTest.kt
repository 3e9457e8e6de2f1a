package org.ktcs.kernel.web.v1.vehicles

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json

class RouteComputationDtosTest : FunSpec({
    test("reads openTCS's route computation request sample") {
        val text = GoldenJson.text("binding/PostVehicleRoutesRequestTOTest.jsonSample.approved.txt")

        V1Json.decodeRequest<PostRouteComputationRequest>(text).toDomain() shouldBe
            RouteComputationQuery(
                sourcePoint = "A",
                destinationPoints = listOf("C", "F"),
                resourcesToAvoid = setOf("A", "B"),
            )
    }

    test("leaves the source point open and avoids nothing when both are absent") {
        V1Json.decodeRequest<PostRouteComputationRequest>("""{"destinationPoints":["C"]}""").toDomain() shouldBe
            RouteComputationQuery(null, listOf("C"), emptySet())
    }

    test("rejects a query without destination points") {
        shouldThrow<InvalidRequestException> {
            V1Json.decodeRequest<PostRouteComputationRequest>("""{"sourcePoint":"A"}""").toDomain()
        }.message shouldBe "destinationPoints is missing"
    }

    test("encodes routes, and a destination without one, exactly as openTCS's response sample") {
        val routes = linkedMapOf(
            "C" to listOf(Route(listOf(step("A", "B"), step("B", "C")), 1376)),
            "E" to emptyList(),
            "F" to listOf(
                Route(
                    listOf(step("D", "E", VehicleOrientation.BACKWARD), step("E", "F", VehicleOrientation.UNDEFINED)),
                    4682,
                ),
            ),
        )

        V1Json.json.encodeToString(
            RouteComputationResponse.serializer(),
            routes.toRouteComputationResponse(),
        ) shouldEqualJsonElement
            GoldenJson.element("binding/PostVehicleRoutesResponseTOTest.jsonSample.approved.txt")
    }
})

private fun step(from: String, to: String, orientation: VehicleOrientation = VehicleOrientation.FORWARD) =
    Step("$from --- $to", from, to, orientation)
