package org.ktcs.kernel.routing

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Link
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.Operations
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation

class DefaultRouterRouteOrderTest : FunSpec({
    // The closer point of Station is the worse choice once the second leg is counted.
    val twoLegs = plant(
        path("S", "P1"),
        path("S", "P2", length = 1500),
        path("P1", "E", length = 3000),
        path("P2", "X", length = 500),
        path("X", "E", length = 500),
        locations = listOf(station("Station", Link("P1"), Link("P2")), station("Other", Link("P2"))),
    )
    val loadThenLeave = order(Destination("Station", "LOAD"), moveTo("E"))
    val pickyStation = plant(
        path("S", "P1"),
        path("S", "P2", length = 500),
        locations = listOf(station("Station", Link("P1"), Link("P2", setOf("UNLOAD")))),
    )

    fun List<DriveOrder>.routePoints() = map { it.route.shouldNotBeNull().points }

    test("picks for each location the linked point that makes the whole order cheapest") {
        val plainCosts = RouterConfiguration(operationPointSurcharge = 0)
        val driveOrders = routerFor(twoLegs, plainCosts).routeOrder(vehicle(), "S", loadThenLeave).shouldNotBeNull()

        driveOrders.routePoints() shouldContainExactly listOf(listOf("S", "P2"), listOf("P2", "X", "E"))
        driveOrders.map { it.route?.costs } shouldContainExactly listOf(1500L, 1000L)
    }

    test("numbers steps from 0 in every drive order and leaves everything else as it was") {
        val driveOrders = routerFor(twoLegs).routeOrder(vehicle(), "S", loadThenLeave).shouldNotBeNull()

        driveOrders.map { it.route?.steps?.map(Step::routeIndex) } shouldContainExactly listOf(listOf(0), listOf(0, 1))
        driveOrders.map { it.copy(route = null) } shouldBe loadThenLeave.driveOrders
        driveOrders.map { it.state }.toSet() shouldBe setOf(DriveOrderState.PRISTINE)
    }

    test("uses only links that permit the operation, falling back to the location type's operations") {
        val router = routerFor(pickyStation)
        fun pointFor(operation: String) =
            router.routeOrder(vehicle(), "S", order(Destination("Station", operation)))?.single()?.route?.points?.last()

        pointFor("LOAD") shouldBe "P1"
        pointFor("UNLOAD") shouldBe "P2"
        pointFor(Operations.NOP) shouldBe "P2"
        pointFor("CHARGE").shouldBeNull()
    }

    test("serves a destination at the start point without moving") {
        val driveOrders = routerFor(twoLegs).routeOrder(vehicle(), "P1", order(Destination("Station", "LOAD")))

        driveOrders?.single()?.route shouldBe Route(listOf(Step(null, null, "P1", VehicleOrientation.UNDEFINED)), 0)
    }

    test("with routeToCurrentPosition the start point competes with the other candidates") {
        val model = twoLegs.copy(paths = listOf(path("P1", "P2", properties = mapOf("tcs:routingCostForward" to "-5"))))
        val configuration = RouterConfiguration(
            algorithm = RoutingAlgorithm.BELLMAN_FORD,
            edgeEvaluators = listOf(EdgeEvaluator.EXPLICIT_PROPERTIES),
        )
        val stationOrder = order(Destination("Station", "LOAD"))

        routerFor(model, configuration).routeOrder(vehicle(), "P1", stationOrder)?.single()?.route?.costs shouldBe 0
        routerFor(model, configuration.copy(routeToCurrentPosition = true))
            .routeOrder(vehicle(), "P1", stationOrder)?.single()?.route?.costs shouldBe -5
    }

    test("honours the resources to avoid: points, paths and the linked points of locations") {
        val router = routerFor(twoLegs)
        fun pointsAvoiding(resources: String) = router.routeOrder(
            vehicle(),
            "S",
            order(Destination("Station", "LOAD"), moveTo("E"), resourcesToAvoid = resources),
        )?.routePoints()
        val viaP1 = listOf(listOf("S", "P1"), listOf("P1", "E"))

        pointsAvoiding("X") shouldBe viaP1
        pointsAvoiding(" P2 --- X ,") shouldBe viaP1
        pointsAvoiding("Other") shouldBe viaP1
        pointsAvoiding("Station").shouldBeNull()
    }

    test("finds no route to a locked location, an unknown target or an unreachable point") {
        val locked = twoLegs.copy(locations = twoLegs.locations.map { it.copy(locked = true) })

        routerFor(locked).routeOrder(vehicle(), "S", loadThenLeave).shouldBeNull()
        routerFor(twoLegs).routeOrder(vehicle(), "S", order(moveTo("Nowhere"))).shouldBeNull()
        routerFor(twoLegs).routeOrder(vehicle(), "E", order(moveTo("S"))).shouldBeNull()
    }

    test("routes an order without drive orders to nothing") {
        routerFor(twoLegs).routeOrder(vehicle(), "S", order()).shouldNotBeNull().shouldBeEmpty()
    }
})
