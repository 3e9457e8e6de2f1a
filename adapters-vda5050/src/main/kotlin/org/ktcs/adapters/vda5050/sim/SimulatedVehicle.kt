package org.ktcs.adapters.vda5050.sim

import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.mqtt.LastWill
import org.ktcs.adapters.vda5050.mqtt.MqttLink
import org.ktcs.adapters.vda5050.protocol.Action
import org.ktcs.adapters.vda5050.protocol.ActionState
import org.ktcs.adapters.vda5050.protocol.AgvPosition
import org.ktcs.adapters.vda5050.protocol.BatteryState
import org.ktcs.adapters.vda5050.protocol.Connection
import org.ktcs.adapters.vda5050.protocol.Edge
import org.ktcs.adapters.vda5050.protocol.EdgeState
import org.ktcs.adapters.vda5050.protocol.InstantActions
import org.ktcs.adapters.vda5050.protocol.Load
import org.ktcs.adapters.vda5050.protocol.Node
import org.ktcs.adapters.vda5050.protocol.NodeState
import org.ktcs.adapters.vda5050.protocol.Order
import org.ktcs.adapters.vda5050.protocol.SafetyState
import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.adapters.vda5050.protocol.Vda5050Json
import org.ktcs.adapters.vda5050.protocol.VehicleError
import org.ktcs.adapters.vda5050.protocol.Visualization
import org.slf4j.LoggerFactory
import java.time.Instant
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.TimeUnit
import kotlin.math.hypot

/** Who a simulated vehicle is and how it moves. */
data class SimulatedVehicleSpec(
    val manufacturer: String,
    val serialNumber: String,
    val topicPrefix: String,
    val startNode: String,
    val startX: Double,
    val startY: Double,
    val mapId: String = "",
    val speedMetresPerSecond: Double = 1.0,
    val actionMillis: Long = 1000,
    val stateIntervalMillis: Long = 1000,
    val visualizationIntervalMillis: Long = 100,
    /** How much faster than real time the vehicle drives and acts (2.0: twice as fast). */
    val timeFactor: Double = 1.0,
)

/**
 * A VDA 5050 2.0 vehicle played in software: it drives along the released nodes of its order at its speed, carries
 * out node actions (pick, drop, charging, anything else takes [SimulatedVehicleSpec.actionMillis]), honours the
 * instant actions, and reports `state` at its interval and on every event, `visualization` more often, and its
 * `connection` (with CONNECTIONBROKEN as its MQTT last will). All its work runs on [executor], one piece at a time
 * per vehicle: the simulator and the bench share a pool of two threads among all vehicles, so a vehicle's tick and an
 * order arriving for it would otherwise change its state at once.
 */
class SimulatedVehicle(
    val spec: SimulatedVehicleSpec,
    endpoint: BrokerEndpoint,
    private val executor: ScheduledExecutorService,
) : AutoCloseable {
    private val log = LoggerFactory.getLogger(SimulatedVehicle::class.java)
    private val topic = spec.topicPrefix
    private val link = MqttLink(
        "sim-${spec.serialNumber}",
        endpoint,
        will = LastWill("$topic/connection", connectionJson(Vda.CONNECTION_BROKEN, 0)),
    ) { up -> if (up) executor.execute { guarded { announceOnline() } } }
    private val headerIds = HashMap<String, Long>()
    private val work = Any() // held by whatever changes the vehicle's state, see the class comment

    // The vehicle's state, touched only on the executor's threads while holding [work].
    private var x = spec.startX
    private var y = spec.startY
    private var theta = 0.0
    private var lastNodeId = spec.startNode
    private var lastNodeSequenceId = 0
    private var orderId = ""
    private var orderUpdateId = 0L
    private val nodes = ArrayDeque<Node>() // not yet reached, base and horizon
    private val edges = ArrayDeque<Edge>()
    private val actionStates = LinkedHashMap<String, ActionState>()
    private val runningActions = ArrayDeque<Action>() // the actions of the node it stands on, in order
    private var actionEndsAt = 0L
    private var paused = false
    private var battery = 100.0
    private var loads = emptyList<Load>()
    private val errors = mutableListOf<VehicleError>()
    private var lastState = 0L
    private var lastVisualization = 0L
    private var tick: java.util.concurrent.ScheduledFuture<*>? = null

    /** Errors a test or the operator makes the vehicle report (FATAL ones stop it). */
    fun raiseError(type: String, level: String = Vda.FATAL, description: String? = null) = executor.execute {
        guarded {
            errors += VehicleError(type, level, description)
            publishState()
        }
    }

    fun clearErrors() = executor.execute {
        guarded {
            errors.clear()
            publishState()
        }
    }

    fun start() {
        link.subscribe("$topic/order", 1) { payload -> executor.execute { guarded { onOrder(payload) } } }
        link.subscribe("$topic/instantActions", 1) { payload ->
            executor.execute { guarded { onInstantActions(payload) } }
        }
        link.connect()
        tick = executor.scheduleAtFixedRate({
            guarded { step(TICK_MILLIS) }
        }, TICK_MILLIS, TICK_MILLIS, TimeUnit.MILLISECONDS)
    }

    /** Goes offline cleanly: publishes OFFLINE, then disconnects (the broker keeps the last will to itself). */
    override fun close() {
        tick?.cancel(false)
        runCatching {
            link.publish(
                "$topic/connection",
                connectionJson(Vda.OFFLINE, next("connection")),
                1,
                retain = true,
            ).get(2, TimeUnit.SECONDS)
        }
        link.close()
    }

    private fun guarded(action: () -> Unit) = synchronized(work) {
        try {
            action()
        } catch (error: RuntimeException) {
            log.warn("simulated vehicle {}: {}", spec.serialNumber, error.toString())
        }
    }

    private fun announceOnline() {
        link.publish("$topic/connection", connectionJson(Vda.ONLINE, next("connection")), 1, retain = true)
        publishState()
    }

    private fun onOrder(payload: ByteArray) {
        val order = Vda5050Json.decodeFromString(Order.serializer(), String(payload))
        when {
            order.orderId == orderId && order.orderUpdateId <= orderUpdateId -> return

            // a repetition: already known
            order.orderId == orderId -> update(order)

            nodes.any { it.released } || edges.any { it.released } ->
                reject("orderError", "order ${order.orderId} arrived while order $orderId is still running")

            order.nodes.firstOrNull()?.nodeId != lastNodeId && order.nodes.first().sequenceId == 0 &&
                distanceTo(order.nodes.first()) > START_TOLERANCE_METRES ->
                reject(
                    "noRouteError",
                    "order ${order.orderId} starts at ${order.nodes.first().nodeId}, the vehicle is at $lastNodeId",
                )

            else -> accept(order)
        }
        publishState()
    }

    private fun accept(order: Order) {
        orderId = order.orderId
        orderUpdateId = order.orderUpdateId
        errors.removeAll { it.errorType in Vda.REJECTIONS }
        actionStates.clear()
        nodes.clear()
        edges.clear()
        nodes += order.nodes
        edges += order.edges
        register(order)
        // The first node is where the vehicle stands: reached at once.
        nodes.firstOrNull()?.let { if (it.released) arrive(it) }
    }

    private fun update(order: Order) {
        val stitch = order.nodes.firstOrNull() ?: return
        val knownBase = (nodes.filter { it.released }.lastOrNull()?.sequenceId) ?: lastNodeSequenceId
        if (stitch.sequenceId != knownBase) {
            reject(
                "orderUpdateError",
                "update ${order.orderUpdateId} of $orderId starts at sequence ${stitch.sequenceId}, the base ends at $knownBase",
            )
            return
        }
        orderUpdateId = order.orderUpdateId
        nodes.removeAll { !it.released }
        edges.removeAll { !it.released }
        nodes += order.nodes.filter { it.sequenceId > stitch.sequenceId }
        edges += order.edges.filter { it.sequenceId > stitch.sequenceId }
        register(order)
    }

    private fun register(order: Order) {
        (order.nodes.flatMap { it.actions } + order.edges.flatMap { it.actions })
            .forEach { actionStates.putIfAbsent(it.actionId, ActionState(it.actionId, "WAITING", it.actionType)) }
    }

    private fun reject(type: String, description: String) {
        errors.removeAll { it.errorType in Vda.REJECTIONS }
        errors += VehicleError(type, Vda.WARNING, description)
    }

    private fun onInstantActions(payload: ByteArray) {
        val message = Vda5050Json.decodeFromString(InstantActions.serializer(), String(payload))
        message.actions.forEach { action ->
            var status = Vda.FINISHED
            when (action.actionType) {
                Vda.CANCEL_ORDER -> cancel()

                Vda.START_PAUSE -> paused = true

                Vda.STOP_PAUSE -> paused = false

                Vda.INIT_POSITION -> initPosition(action)

                Vda.FACTSHEET_REQUEST -> link.publish(
                    "$topic/factsheet",
                    SimulatorFactsheet.json(spec).toByteArray(),
                    0,
                )

                Vda.STATE_REQUEST -> Unit

                else -> status = Vda.FAILED
            }
            actionStates[action.actionId] = ActionState(action.actionId, status, action.actionType)
        }
        publishState()
    }

    private fun cancel() {
        nodes.clear()
        edges.clear()
        runningActions.clear()
        actionStates.replaceAll { _, s ->
            if (s.actionStatus == Vda.FINISHED || s.actionStatus == Vda.FAILED) s else s.copy(actionStatus = Vda.FAILED)
        }
    }

    private fun initPosition(action: Action) {
        val parameters = action.actionParameters.associate { it.key to it.value }
        (parameters["x"] as? JsonPrimitive)?.doubleOrNull?.let { x = it }
        (parameters["y"] as? JsonPrimitive)?.doubleOrNull?.let { y = it }
        (parameters["theta"] as? JsonPrimitive)?.doubleOrNull?.let { theta = it }
        (parameters["lastNodeId"] as? JsonPrimitive)?.content?.let { lastNodeId = it }
    }

    /** Advances the vehicle by [millis]: finishes a running action, or drives towards the next released node. */
    private fun step(millis: Long) {
        val now = System.currentTimeMillis()
        if (!paused && errors.none { it.errorLevel == Vda.FATAL }) {
            if (runningActions.isNotEmpty()) {
                if (now >= actionEndsAt) finishAction(now)
            } else {
                drive(millis)
            }
        }
        if (now - lastVisualization >= spec.visualizationIntervalMillis) publishVisualization(now)
        if (now - lastState >= spec.stateIntervalMillis) publishState()
    }

    private fun drive(millis: Long) {
        val target = nodes.firstOrNull()?.takeIf { it.released } ?: return
        val edge = edges.firstOrNull()?.takeIf { it.released && it.endNodeId == target.nodeId }
        val position = target.nodePosition ?: return arrive(target)
        val speed = minOf(spec.speedMetresPerSecond, edge?.maxSpeed ?: Double.MAX_VALUE)
        val dx = position.x - x
        val dy = position.y - y
        val distance = hypot(dx, dy)
        val travel = speed * spec.timeFactor * millis / 1000.0
        if (distance <= travel) {
            x = position.x
            y = position.y
            arrive(target)
        } else {
            x += dx / distance * travel
            y += dy / distance * travel
            theta = Math.atan2(dy, dx)
            battery = (battery - travel * DRAIN_PER_METRE).coerceAtLeast(0.0)
        }
    }

    private fun arrive(node: Node) {
        nodes.removeFirst()
        if (edges.firstOrNull()?.endNodeId == node.nodeId) edges.removeFirst()
        lastNodeId = node.nodeId
        lastNodeSequenceId = node.sequenceId
        runningActions += node.actions
        startNextAction(System.currentTimeMillis())
        publishState()
    }

    private fun startNextAction(now: Long) {
        val action = runningActions.firstOrNull() ?: return
        actionStates[action.actionId] = ActionState(action.actionId, "RUNNING", action.actionType)
        actionEndsAt = now + (spec.actionMillis / spec.timeFactor).toLong()
    }

    private fun finishAction(now: Long) {
        val action = runningActions.removeFirst()
        when (action.actionType) {
            Vda.PICK -> loads = listOf(Load(loadId = "load-${now % 100_000}", loadPosition = "LHD-0"))
            Vda.DROP -> loads = emptyList()
            Vda.START_CHARGING -> battery = 100.0
        }
        actionStates[action.actionId] = ActionState(action.actionId, Vda.FINISHED, action.actionType)
        startNextAction(now)
        publishState()
    }

    private fun publishState() {
        lastState = System.currentTimeMillis()
        val state = State(
            headerId = next("state"),
            timestamp = Instant.now().toString(),
            version = Vda.PROTOCOL_VERSION,
            manufacturer = spec.manufacturer,
            serialNumber = spec.serialNumber,
            orderId = orderId,
            orderUpdateId = orderUpdateId,
            lastNodeId = lastNodeId,
            lastNodeSequenceId = lastNodeSequenceId,
            nodeStates = nodes.map { NodeState(it.nodeId, it.sequenceId, it.released) },
            edgeStates = edges.map { EdgeState(it.edgeId, it.sequenceId, it.released) },
            driving = !paused && runningActions.isEmpty() && nodes.any { it.released },
            actionStates = actionStates.values.toList(),
            batteryState = BatteryState(battery, charging = false),
            operatingMode = "AUTOMATIC",
            errors = errors.toList(),
            safetyState = SafetyState("NONE", false),
            paused = paused,
            agvPosition = AgvPosition(x, y, theta, spec.mapId, positionInitialized = true),
            loads = loads,
        )
        link.publish("$topic/state", Vda5050Json.encodeToString(State.serializer(), state).toByteArray(), 0)
    }

    private fun publishVisualization(now: Long) {
        lastVisualization = now
        val message = Visualization(
            next("visualization"),
            Instant.now().toString(),
            Vda.PROTOCOL_VERSION,
            spec.manufacturer,
            spec.serialNumber,
            AgvPosition(x, y, theta, spec.mapId, positionInitialized = true),
        )
        link.publish(
            "$topic/visualization",
            Vda5050Json.encodeToString(Visualization.serializer(), message).toByteArray(),
            0,
        )
    }

    private fun connectionJson(state: String, headerId: Long): ByteArray = Vda5050Json.encodeToString(
        Connection.serializer(),
        Connection(
            headerId,
            Instant.now().toString(),
            Vda.PROTOCOL_VERSION,
            spec.manufacturer,
            spec.serialNumber,
            state,
        ),
    ).toByteArray()

    private fun distanceTo(node: Node): Double = node.nodePosition?.let { hypot(it.x - x, it.y - y) } ?: 0.0

    private fun next(topic: String): Long = synchronized(headerIds) { headerIds.merge(topic, 1L, Long::plus)!! - 1 }

    private companion object {
        const val TICK_MILLIS = 50L
        const val START_TOLERANCE_METRES = 0.5
        const val DRAIN_PER_METRE = 0.01
    }
}
