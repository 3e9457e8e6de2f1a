package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.protocol.Action
import org.ktcs.adapters.vda5050.protocol.Edge
import org.ktcs.adapters.vda5050.protocol.Node
import org.ktcs.adapters.vda5050.protocol.NodePosition
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.model.PlantModel

/** A movement command as part of a VDA 5050 order: its edge, its end node and the actions at that node. */
internal data class SentStep(val command: MovementCommand, val edge: Edge?, val node: Node) {
    val actionIds: Set<String> get() = node.actions.map { it.actionId }.toSet()
}

/** One order message to publish: its update id and its released (base) and horizon nodes and edges. */
internal data class OrderUpdate(
    val orderId: String,
    val orderUpdateId: Long,
    val nodes: List<Node>,
    val edges: List<Edge>,
)

/**
 * One VDA 5050 order (one kTCS drive order): the steps released to the vehicle so far (the base, which only grows)
 * and how far the vehicle has acknowledged them. Each [extend] with a newly allocated step makes an order update
 * with the next `orderUpdateId`, starting at the stitching node (the last base node the vehicle knows) and followed by
 * the horizon. Confined to the kernel context.
 */
internal class OrderTracker(
    val orderId: String,
    private val plant: () -> PlantModel,
    private val mapId: (String) -> String,
    private val actions: ActionMapping,
) {
    private val steps = mutableListOf<SentStep>()
    private val baseNodes = mutableListOf<Node>() // every node released in this order, finished ones too
    private val baseEdges = mutableListOf<Edge>()
    private var stitchIndex = 0 // index into baseNodes() of the last base node the vehicle has acknowledged
    private var pendingStitchIndex = 0
    private var updateId = -1L

    /** The update the vehicle has not acknowledged yet, if any. */
    var unacknowledged: OrderUpdate? = null
        private set

    val sent: List<SentStep> get() = steps

    /** Adds [command] to the base and returns the update to publish, with [horizon] (point and path names) after it. */
    fun extend(command: MovementCommand, startPoint: String, horizon: List<Pair<String?, String>>): OrderUpdate {
        if (baseNodes.isEmpty() && command.step.path == null) {
            // A route that starts where the vehicle stands: the order is that one node, with the operation's actions.
            val only =
                node(command.step.destinationPoint, 0, released = true, extraActions = destinationActions(command))
            steps += SentStep(command, null, only)
            baseNodes += only
            return update(horizon)
        }
        if (baseNodes.isEmpty()) {
            baseNodes += node(command.step.sourcePoint ?: startPoint, 0, released = true, extraActions = emptyList())
        }
        val previous = baseNodes.last()
        val sequence = previous.sequenceId + 2
        val path = command.step.path
        val edge = path?.let { edge(it, previous.nodeId, command.step.destinationPoint, sequence - 1, released = true) }
        val node =
            node(command.step.destinationPoint, sequence, released = true, extraActions = destinationActions(command))
        steps += SentStep(command, edge, node)
        baseNodes += node
        edge?.let { baseEdges += it }
        return update(horizon)
    }

    /** The vehicle reflected update [orderUpdateId] of this order in its state. */
    fun acknowledge(orderUpdateId: Long) {
        val waiting = unacknowledged ?: return
        if (orderUpdateId >= waiting.orderUpdateId) {
            stitchIndex = pendingStitchIndex
            unacknowledged = null
        }
    }

    /** Removes the steps the vehicle has finished. */
    fun completed(step: SentStep) {
        steps.remove(step)
    }

    private fun update(horizon: List<Pair<String?, String>>): OrderUpdate {
        val fromSequence = baseNodes[stitchIndex.coerceAtMost(baseNodes.lastIndex)].sequenceId
        val nodes = baseNodes.filter { it.sequenceId >= fromSequence }.toMutableList()
        val edges = baseEdges.filter { it.sequenceId > fromSequence }.toMutableList()
        var sequence = baseNodes.last().sequenceId
        var last = baseNodes.last().nodeId
        horizon.forEach { (path, point) ->
            if (path != null) edges += edge(path, last, point, sequence + 1, released = false)
            nodes += node(point, sequence + 2, released = false, extraActions = emptyList())
            sequence += 2
            last = point
        }
        pendingStitchIndex = baseNodes.lastIndex
        updateId++
        return OrderUpdate(orderId, updateId, nodes, edges).also { unacknowledged = it }
    }

    private fun destinationActions(command: MovementCommand): List<Action> {
        val model = plant()
        val pointActions = model.point(
            command.step.destinationPoint,
        )?.properties?.let(actions::elementActions).orEmpty()
        if (!command.hasOperation) return pointActions
        val location = command.opLocation?.let(model::location)
        val sources = listOfNotNull(
            location?.type?.let(model::locationType)?.properties,
            location?.properties,
            command.properties,
        )
        return pointActions + location?.properties?.let(actions::elementActions).orEmpty() +
            actions.destinationAction(command.operation, sources)
    }

    private fun node(point: String, sequence: Int, released: Boolean, extraActions: List<Action>): Node {
        val p = plant().point(point)
        val position = p?.let {
            NodePosition(
                x = it.pose.position.x / MM_PER_M,
                y = it.pose.position.y / MM_PER_M,
                mapId = mapId(point),
                theta = it.pose.orientationAngle.takeIf { angle -> !angle.isNaN() }?.let(Math::toRadians)
                    ?.let(::normalised),
                allowedDeviationXY = it.properties["vda5050:deviationXY"]?.toDoubleOrNull(),
                allowedDeviationTheta = it.properties["vda5050:deviationTheta"]?.toDoubleOrNull()?.let(Math::toRadians),
            )
        }
        return Node(point, sequence, released, if (released) extraActions else emptyList(), position)
    }

    private fun edge(path: String, from: String, to: String, sequence: Int, released: Boolean): Edge {
        val p = plant().path(path)
        val forward = p == null || p.destinationPoint == to
        val speed = p?.let { if (forward) it.maxVelocity else it.maxReverseVelocity }?.takeIf { it > 0 }
        return Edge(
            edgeId = path,
            sequenceId = sequence,
            released = released,
            startNodeId = from,
            endNodeId = to,
            actions = if (released) p?.properties?.let(actions::elementActions).orEmpty() else emptyList(),
            maxSpeed = speed?.let { it / MM_PER_M },
            length = p?.length?.let { it / MM_PER_M },
        )
    }

    private fun normalised(radians: Double): Double =
        Math.IEEEremainder(radians, 2 * Math.PI).let { if (it <= -Math.PI) it + 2 * Math.PI else it }

    private companion object {
        const val MM_PER_M = 1000.0
    }
}
