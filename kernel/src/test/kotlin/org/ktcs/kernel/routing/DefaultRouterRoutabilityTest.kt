package org.ktcs.kernel.routing

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.booleans.shouldBeFalse
import io.kotest.matchers.booleans.shouldBeTrue
import org.ktcs.api.model.Link
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations

class DefaultRouterRoutabilityTest : FunSpec({
    val oneWay = plant(
        path("A", "B"),
        path("B", "C"),
        path("C", "D", maxVelocity = 0, maxReverseVelocity = 0),
        locations = listOf(station("Station", Link("A"), Link("B", setOf("UNLOAD"))), station("Far", Link("D"))),
    )
    val router = routerFor(oneWay)

    test("an order is routable when each destination can be reached from the one before") {
        router.isGenerallyRoutable(order(Destination("Station", "LOAD"), moveTo("C"))).shouldBeTrue()
        router.isGenerallyRoutable(order(moveTo("D"))).shouldBeTrue()
    }

    test("an order is not routable when a later destination cannot be reached from an earlier one") {
        router.isGenerallyRoutable(order(moveTo("C"), Destination("Station", "LOAD"))).shouldBeFalse()
        router.isGenerallyRoutable(order(moveTo("A"), Destination("Far", Operations.NOP))).shouldBeFalse()
    }

    test("only links permitting the operation count") {
        router.isGenerallyRoutable(order(moveTo("B"), Destination("Station", "UNLOAD"))).shouldBeTrue()
        router.isGenerallyRoutable(order(moveTo("B"), Destination("Station", "LOAD"))).shouldBeFalse()
        router.isGenerallyRoutable(order(Destination("Station", "CHARGE"))).shouldBeFalse()
    }

    test("locks and cost functions do not matter") {
        val locked = oneWay.copy(
            paths = oneWay.paths.map {
                it.copy(locked = true, properties = mapOf("tcs:routingCostForward" to "Infinity"))
            },
            locations = oneWay.locations.map { it.copy(locked = true) },
        )
        val explicit = RouterConfiguration(edgeEvaluators = listOf(EdgeEvaluator.EXPLICIT_PROPERTIES))

        routerFor(
            locked,
            explicit,
        ).isGenerallyRoutable(order(Destination("Station", "LOAD"), moveTo("C"))).shouldBeTrue()
    }

    test("an unknown destination is not routable, an order without destinations is") {
        router.isGenerallyRoutable(order(moveTo("Nowhere"))).shouldBeFalse()
        router.isGenerallyRoutable(order()).shouldBeTrue()
    }
})
