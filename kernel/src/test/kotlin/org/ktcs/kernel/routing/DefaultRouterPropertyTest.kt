package org.ktcs.kernel.routing

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldBeSortedBy
import io.kotest.matchers.collections.shouldNotContainDuplicates
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.longs.shouldBeGreaterThanOrEqual
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.property.checkAll
import org.ktcs.api.model.Location
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.Route

class DefaultRouterPropertyTest : FunSpec({
    fun GridCase.router(algorithm: RoutingAlgorithm = RoutingAlgorithm.DIJKSTRA) =
        routerFor(
            model,
            RouterConfiguration(algorithm = algorithm, edgeEvaluators = evaluators, operationPointSurcharge = 0),
        )

    fun GridCase.shouldBeValid(route: Route, from: String, to: String) {
        if (from == to) {
            route shouldBe routeStayingAt(from)
            return
        }
        val directions = directions().associateBy { it.path.name to it.orientation }
        route.steps.first().sourcePoint shouldBe from
        route.steps.last().destinationPoint shouldBe to
        route.steps.zipWithNext().forEach { (step, next) -> step.destinationPoint shouldBe next.sourcePoint }
        route.steps.mapIndexed { index, step -> step.routeIndex shouldBe index }
        val costs = route.steps.map { step ->
            val direction = directions[step.path to step.vehicleOrientation].shouldNotBeNull()
            step.sourcePoint shouldBe direction.from
            costOf(direction).shouldNotBeNull()
        }
        route.costs shouldBe costs.sum()
        route.costs shouldBeGreaterThanOrEqual 0
    }

    test("routes connect source to destination, cost what their steps cost and none is cheaper") {
        checkAll(300, gridCases) { case ->
            val routes = case.router().routes(case.vehicle, case.source, case.destination, maxRoutes = 3)
            val cheapest = case.cheapestCostsFrom(case.source)[case.destination]

            if (cheapest == null) routes.shouldBeEmpty() else routes.first().costs shouldBe cheapest
            routes.forEach { case.shouldBeValid(it, case.source, case.destination) }
            routes.shouldBeSortedBy { it.costs }
            routes.shouldNotContainDuplicates()
            routes.size shouldBeLessThanOrEqual 3
        }
    }

    test("every algorithm finds routes of the same cost") {
        checkAll(100, gridCases) { case ->
            val costs = RoutingAlgorithm.entries.map { algorithm ->
                case.router(algorithm).routes(case.vehicle, case.source, case.destination).firstOrNull()?.costs
            }

            costs.toSet().size shouldBe 1
        }
    }

    test("the costs to a point, from one search backwards, are the cheapest costs from every point") {
        checkAll(200, gridCases) { case ->
            val router = case.router()
            val toDestination = router.costsTo(case.vehicle, case.destination)

            for (point in case.model.points.map { it.name } + "no such point") {
                toDestination(point) shouldBe case.cheapestCostsFrom(point)[case.destination]
            }
            router.costsTo(case.vehicle, "no such point")(case.source) shouldBe null
        }
    }

    test("order routes visit one linked point per location and are as cheap as trying every combination") {
        checkAll(200, gridCases) { case ->
            val stations = case.model.locations
            val order = order(*stations.map { Destination(it.name, Operations.NOP) }.toTypedArray())
            val driveOrders = case.router().routeOrder(case.vehicle, case.source, order)
            val cheapest = case.cheapestTrip(stations)

            if (cheapest == null) {
                driveOrders shouldBe null
            } else {
                val routes = driveOrders.shouldNotBeNull().map { it.route.shouldNotBeNull() }
                val ends = routes.map { it.steps.last().destinationPoint }
                (listOf(case.source) + ends).zipWithNext().zip(routes) { (from, to), route ->
                    case.shouldBeValid(route, from, to)
                }
                ends.zip(stations) { end, station -> station.links.map { it.point } shouldContain end }
                routes.sumOf { it.costs } shouldBe cheapest
            }
        }
    }
})

/** The cheapest total cost of visiting one linked point of each of [stations] in turn, trying every combination. */
private fun GridCase.cheapestTrip(stations: List<Location>): Long? {
    var costs = mapOf(source to 0L)
    for (station in stations) {
        costs = station.links.map { it.point }.distinct().mapNotNull { point ->
            costs.mapNotNull { (from, cost) -> cheapestCostsFrom(from)[point]?.plus(cost) }.minOrNull()?.let {
                point to
                    it
            }
        }.toMap()
    }
    return costs.values.minOrNull()
}

private infix fun List<String>.shouldContain(element: String) = (element in this) shouldBe true
