package org.ktcs.kernel.routing

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.booleans.shouldBeFalse
import io.kotest.matchers.booleans.shouldBeTrue
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.pair
import io.kotest.property.checkAll
import org.jgrapht.Graphs
import org.jgrapht.graph.DirectedPseudograph
import org.ktcs.api.order.Destination
import org.ktcs.api.order.VehicleOrientation

class ReachabilityTest : FunSpec({
    test("points of one cycle reach each other; a one-way exit is not a way back") {
        val reachability = Reachability(graphOf("A" to "B", "B" to "C", "C" to "A", "C" to "D", "D" to "E"))

        reachability.reaches("A", "C").shouldBeTrue()
        reachability.reaches("C", "B").shouldBeTrue()
        reachability.reaches("A", "E").shouldBeTrue()
        reachability.reaches("E", "A").shouldBeFalse()
        reachability.reaches("D", "C").shouldBeFalse()
        reachability.reaches("X", "A").shouldBeFalse()
    }

    test("answers as a search of the graph would, on random graphs") {
        val edges = Arb.list(Arb.pair(Arb.int(0..11), Arb.int(0..11)), 0..30)
        checkAll(200, edges) { pairs ->
            val graph = graphOf(*pairs.map { (a, b) -> "P$a" to "P$b" }.toTypedArray())
            val reachability = Reachability(graph)
            for (from in graph.vertexSet()) {
                val searched = searchFrom(graph, from)
                for (to in graph.vertexSet()) reachability.reaches(from, to) shouldBe (to in searched)
            }
        }
    }

    test("the router answers routability from the topology it was last given") {
        val open = plant(path("A", "B"), path("B", "C"))
        val router = routerFor(open)
        val toC = order(moveTo("A"), moveTo("C"))
        router.isGenerallyRoutable(toC).shouldBeTrue()

        router.updateTopology(open.copy(paths = open.paths.filter { it.destinationPoint != "C" }))
        router.isGenerallyRoutable(toC).shouldBeFalse()

        router.updateTopology(open)
        router.isGenerallyRoutable(order(moveTo("C"), Destination("A", "MOVE"))).shouldBeFalse()
        router.isGenerallyRoutable(toC).shouldBeTrue()
    }
})

private fun graphOf(vararg edges: Pair<String, String>): RoutingGraph {
    val graph = DirectedPseudograph<String, RoutingEdge>(RoutingEdge::class.java)
    edges.forEach { (a, b) ->
        graph.addVertex(a)
        graph.addVertex(b)
        graph.addEdge(a, b, RoutingEdge("$a --- $b", a, b, VehicleOrientation.FORWARD, 1))
    }
    return graph
}

private fun searchFrom(graph: RoutingGraph, start: String): Set<String> {
    val visited = hashSetOf(start)
    val queue = ArrayDeque(listOf(start))
    while (queue.isNotEmpty()) {
        Graphs.successorListOf(graph, queue.removeFirst()).forEach { if (visited.add(it)) queue.addLast(it) }
    }
    return visited
}
