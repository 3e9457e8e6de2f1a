package org.ktcs.kernel.routing

import org.jgrapht.Graph
import org.jgrapht.graph.DirectedWeightedPseudograph
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation

/**
 * One drivable direction of a path: an edge from [source] to [target] of a routing graph, whose weight is [cost].
 * Compared by identity, as each graph holds its own edges.
 */
internal class RoutingEdge(
    val path: String,
    val source: String,
    val target: String,
    val orientation: VehicleOrientation,
    val cost: Long,
) {
    fun toStep(routeIndex: Int): Step = Step(path, source, target, orientation, routeIndex)

    override fun toString(): String = "$path ($orientation)"
}

internal typealias RoutingGraph = Graph<String, RoutingEdge>

/**
 * The graph whose vertices are the points of [model] and whose edges are the path directions [costOf] allows: forward
 * where a path's maximum velocity is not 0, backward where its maximum reverse velocity is not 0. Locked paths are
 * left out unless [includeLocked].
 */
internal fun buildRoutingGraph(
    model: PlantModel,
    includeLocked: Boolean,
    costOf: (Path, VehicleOrientation) -> Long?,
): RoutingGraph {
    val graph = DirectedWeightedPseudograph<String, RoutingEdge>(RoutingEdge::class.java)
    model.points.forEach { graph.addVertex(it.name) }
    for (path in model.paths) {
        if (path.locked && !includeLocked) continue
        if (path.isNavigableForward) {
            graph.addDirection(path, path.sourcePoint, path.destinationPoint, VehicleOrientation.FORWARD, costOf)
        }
        if (path.isNavigableReverse) {
            graph.addDirection(path, path.destinationPoint, path.sourcePoint, VehicleOrientation.BACKWARD, costOf)
        }
    }
    return graph
}

private fun RoutingGraph.addDirection(
    path: Path,
    source: String,
    target: String,
    orientation: VehicleOrientation,
    costOf: (Path, VehicleOrientation) -> Long?,
) {
    if (!containsVertex(source) || !containsVertex(target)) return
    val cost = costOf(path, orientation) ?: return
    val edge = RoutingEdge(path.name, source, target, orientation, cost)
    addEdge(source, target, edge)
    setEdgeWeight(edge, cost.toDouble())
}
