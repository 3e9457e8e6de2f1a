package org.ktcs.kernel.routing

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.property.checkAll
import org.jgrapht.alg.shortestpath.DijkstraShortestPath
import org.ktcs.api.model.Link
import org.ktcs.api.order.Destination
import org.ktcs.kernel.simulation.TrafficGrid
import kotlin.random.Random

/**
 * The router keeps its searches per source point (resumed for farther points) until the topology changes: a router
 * asked many questions must answer each as a fresh search would, and no kept search may outlive its topology or
 * answer for a route that avoids resources.
 */
class KeptSearchesTest : FunSpec({
    val detour =
        plant(path("A", "B"), path("B", "D"), path("A", "D", length = 5000), path("A", "C"), path("C", "D", 1500))

    test("a router asked many questions in a row answers each as a search of its own would") {
        checkAll(150, gridCases) { case ->
            val router =
                routerFor(
                    case.model,
                    RouterConfiguration(edgeEvaluators = case.evaluators, operationPointSurcharge = 0),
                )
            val points = case.model.points.map { it.name }.shuffled(Random(case.source.hashCode()))
            for (source in points) {
                val cheapest = case.cheapestCostsFrom(source)
                val costs = router.costsFrom(case.vehicle, source)
                // Nearest first and farthest first: the kept search is resumed, and asked about points it settled.
                val targets = points.sortedBy { cheapest[it] ?: Long.MAX_VALUE }
                for (target in targets + targets.asReversed()) {
                    costs(target) shouldBe cheapest[target]
                    router.routes(case.vehicle, source, target).firstOrNull()?.costs shouldBe cheapest[target]
                }
            }
        }
    }

    test(
        "among equally cheap routes it picks the one JGraphT's Dijkstra picks, so the vehicles' traffic stays the same",
    ) {
        // A traffic grid has many routes of equal costs between two points; another tie-break picks other ones.
        val model = TrafficGrid(8, 8, vehicles = 4).build()
        val configuration = RouterConfiguration(operationPointSurcharge = 0)
        val costs = EdgeCosts(model, configuration, configuration.graphKeyOf(model.vehicles.first()))
        val graph = buildRoutingGraph(model, includeLocked = false, costs::of)
        val reference = DijkstraShortestPath(graph)
        val search = RouteSearch(graph, RoutingAlgorithm.DIJKSTRA)
        val points = model.points.map { it.name }
        for (source in points) {
            val routes = search.cheapestFrom(source, points)
            val expected = reference.getPaths(source)
            for (target in points.filter { it != source }) {
                routes[target]?.steps?.map { it.path } shouldBe expected.getPath(target)?.edgeList?.map { it.path }
            }
        }
    }

    test("a new topology starts from new searches") {
        val router = routerFor(detour)
        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "B", "D")

        router.updateTopology(detour.copy(paths = detour.paths.map { it.copy(locked = it.name == "A --- B") }))

        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "C", "D")
        router.costsFrom(vehicle(), "A")("D") shouldBe 2500
    }

    test("a route that avoids resources neither uses nor changes the kept searches") {
        val model = detour.copy(locations = listOf(station("Station-D", Link("D"))))
        val router = routerFor(model, RouterConfiguration(operationPointSurcharge = 0))
        val toStation = Destination("Station-D", "LOAD")
        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "B", "D")

        val avoiding = router.routeOrder(vehicle(), "A", order(toStation, resourcesToAvoid = "B")).shouldNotBeNull()

        avoiding.single().route.shouldNotBeNull().points shouldContainExactly listOf("A", "C", "D")
        router.route("A", "D").shouldNotBeNull().points shouldContainExactly listOf("A", "B", "D")
        router.costsFrom(vehicle(), "A")("D") shouldBe 2000
    }
})
