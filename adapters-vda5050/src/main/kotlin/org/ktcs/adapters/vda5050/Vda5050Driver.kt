package org.ktcs.adapters.vda5050

import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.ktcs.adapters.vda5050.protocol.Action
import org.ktcs.adapters.vda5050.protocol.ActionParameter
import org.ktcs.adapters.vda5050.protocol.Connection
import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.adapters.vda5050.protocol.Visualization
import org.ktcs.api.driver.BasicVehicleDriver
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import org.slf4j.LoggerFactory
import java.time.Instant

/**
 * Drives one VDA 5050 vehicle over MQTT. The scheduler's allocated steps (the commands [BasicVehicleDriver] holds,
 * up to `vda5050:maxStepsBase`) form the order's base, the rest of the route its horizon; every newly allocated step
 * is an order update. `state` messages finish the commands whose edge and node the vehicle no longer reports (and
 * whose actions finished). Messages arrive on the link's threads (kTCS's MQTT client, or the embedded broker's): they
 * are validated and parsed there and handled in the kernel context.
 */
class Vda5050Driver(
    vehicleName: String,
    context: DriverContext,
    private val properties: Vda5050Properties,
    private val broker: Vda5050Broker,
    private val defaultMapId: String,
) : BasicVehicleDriver(vehicleName, context, properties.maxStepsBase, properties.rechargeOperation) {
    private val log = LoggerFactory.getLogger(Vda5050Driver::class.java)
    private val actions = ActionMapping(properties, context.vehicle().properties)
    private val topics =
        VehicleTopics(vehicleName, properties, broker::messages, broker::connections, sending = broker.sending)
    private var orderCount = 0
    private var order: OrderTracker? = null
    private var connectionState = "UNKNOWN"
    private val stateFilter = StateFilter()

    // Set on the link's thread for every state message, also those that are not worth a kernel task.
    @Volatile private var lastState: State? = null

    @Volatile private var lastStateAt: Instant? = null
    private var factsheet: JsonObject? = null
    private var pendingCancel: Action? = null
    private var cancelSentAt = 0L
    private var orderSentAt = 0L
    private val deferred = ArrayDeque<MovementCommand>()
    private var rejections = 0

    private val reports = VehicleReports(vehicleName, context, properties)

    override fun onEnabled() {
        reports.reset()
        stateFilter.reset()
        listen()
    }

    private fun listen() = topics.listen(::received)

    override fun onDisabled() {
        topics.stopListening()
        order = null
        deferred.clear()
    }

    override fun canProcess(order: TransportOrder): Explained = when {
        connectionState != Vda.ONLINE -> Explained.no("vehicle $vehicleName is $connectionState")
        else -> Explained.YES
    }

    /** openTCS's `vda5050:maxDistanceBase`: no further command once the queued ones cover that many mm. */
    override fun canAcceptNextCommand(): Boolean =
        super.canAcceptNextCommand() && (
            properties.maxDistanceBase == Long.MAX_VALUE ||
                pendingCommands.sumOf { command -> command.step.path?.let(context.plantModel::path)?.length ?: 0L } <
                properties.maxDistanceBase
            )

    override fun sendCommand(command: MovementCommand) {
        if (pendingCancel != null || order?.unacknowledged != null) {
            deferred.addLast(command) // sent once the vehicle confirmed the cancellation or the previous update
            return
        }
        release(command)
    }

    private fun release(command: MovementCommand) {
        val current = order?.takeIf { it.orderId.startsWith("${orderPrefix(command)}-") }
            ?: OrderTracker("${orderPrefix(command)}-${++orderCount}", { context.plantModel }, ::mapIdOf, actions)
                .also { order = it }
        val start = context.vehicle().currentPosition ?: command.step.sourcePoint ?: command.step.destinationPoint
        publishOrder(current.extend(command, start, horizonAfter(command)))
    }

    private fun orderPrefix(command: MovementCommand) = "${command.transportOrder}/${command.driveOrder}"

    override fun onCommandQueueCleared() = cancelOrder()

    /** Drops the vehicle's order: cancelOrder, and no new order until the vehicle has confirmed it. */
    private fun cancelOrder() {
        deferred.clear()
        if (order == null) return
        order = null
        val cancel = Action(Vda.CANCEL_ORDER, actions.newId(), "NONE")
        pendingCancel = cancel
        cancelSentAt = System.currentTimeMillis()
        stateFilter.needEvery(true)
        sendInstantActions(listOf(cancel))
    }

    override fun onPaused(paused: Boolean) =
        sendInstantActions(listOf(Action(if (paused) Vda.START_PAUSE else Vda.STOP_PAUSE, actions.newId(), "NONE")))

    override fun processMessage(message: DriverMessage) {
        val action = when (message.type) {
            INIT_POSITION -> initPosition(
                message.parameters["point"] ?: throw IllegalArgumentException("parameter 'point' is missing"),
            )

            STATE_REQUEST -> Action(Vda.STATE_REQUEST, actions.newId(), "NONE")

            FACTSHEET_REQUEST -> Action(Vda.FACTSHEET_REQUEST, actions.newId(), "NONE")

            START_PAUSE -> Action(Vda.START_PAUSE, actions.newId(), "NONE")

            STOP_PAUSE -> Action(Vda.STOP_PAUSE, actions.newId(), "NONE")

            else -> throw IllegalArgumentException("unknown message type '${message.type}'")
        }
        sendInstantActions(listOf(action))
    }

    override fun panelState(): Map<String, String> = buildMap {
        put("connection", connectionState)
        put("lastStateAt", lastStateAt?.toString() ?: "")
        put(
            "stateAgeMillis",
            lastStateAt?.let {
                (context.clock.now().toEpochMilli() - it.toEpochMilli()).toString()
            }.orEmpty(),
        )
        put("errors", lastState?.errors?.joinToString("; ") { it.described() }.orEmpty())
        put("orderId", order?.orderId ?: lastState?.orderId.orEmpty())
        put("orderUpdateId", lastState?.orderUpdateId?.toString().orEmpty())
        put("topicPrefix", properties.topicPrefix)
        put("factsheet", factsheet?.toString().orEmpty())
    }

    private fun initPosition(point: String): Action {
        val p = context.plantModel.point(point) ?: throw IllegalArgumentException("unknown point '$point'")
        val theta = p.pose.orientationAngle.takeIf { !it.isNaN() }?.let(Math::toRadians) ?: 0.0
        val parameters = listOf(
            ActionParameter("x", JsonPrimitive(p.pose.position.x / VehicleReports.MM_PER_M)),
            ActionParameter("y", JsonPrimitive(p.pose.position.y / VehicleReports.MM_PER_M)),
            ActionParameter("theta", JsonPrimitive(theta)),
            ActionParameter("mapId", JsonPrimitive(mapIdOf(point))),
            ActionParameter("lastNodeId", JsonPrimitive(point)),
        )
        return Action(Vda.INIT_POSITION, actions.newId(), "HARD", parameters)
    }

    /** The points and paths of the route after [command] that the scheduler has not allocated yet, as (path, point). */
    private fun horizonAfter(command: MovementCommand): List<Pair<String?, String>> {
        val model = context.plantModel
        val claimed = context.vehicle().claimedResources
        val start = claimed.indexOfFirst { command.step.path != null && command.step.path in it } + 1
        val steps = claimed.drop(start).map { set ->
            val path = set.firstOrNull { model.path(it) != null }
            path to set.firstOrNull { model.point(it) != null }
        }
        val limit = minOf(properties.maxStepsHorizon, factsheetLimit("order.nodes"))
        var last = command.step.destinationPoint
        return steps.mapNotNull { (path, point) ->
            val p = path?.let(model::path) ?: return@mapNotNull null
            val next = point ?: if (p.sourcePoint == last) p.destinationPoint else p.sourcePoint
            last = next
            path to next
        }.take(limit)
    }

    private fun factsheetLimit(array: String): Int = runCatching {
        val lens = (factsheet?.get("protocolLimits") as? JsonObject)?.get("maxArrayLens") as? JsonObject
        val nodes = (lens?.get(array) as? JsonPrimitive)?.content?.toInt()
        nodes?.let { (it - properties.maxStepsBase - 1).coerceAtLeast(0) }
    }.getOrNull() ?: Int.MAX_VALUE

    private fun mapIdOf(point: String): String =
        context.plantModel.point(point)?.properties?.get("vda5050:mapId") ?: properties.mapId ?: defaultMapId

    private fun publishOrder(update: OrderUpdate) {
        orderSentAt = System.currentTimeMillis()
        stateFilter.needEvery(true)
        topics.publishOrder(update)
    }

    private fun sendInstantActions(list: List<Action>) = topics.publishInstantActions(list)

    /**
     * On the link's thread, a validated and parsed message: handled in the kernel context, a state message only if it
     * is worth it ([StateFilter]).
     */
    private fun received(message: Any) {
        when (message) {
            is State -> {
                message.agvPosition?.let { reports.pose(it.x, it.y, it.theta) }
                lastState = message
                lastStateAt = context.clock.now()
                if (stateFilter.worthATask(message)) {
                    inKernel {
                        onState(message)
                        stateFilter.needEvery(order?.unacknowledged != null || pendingCancel != null)
                    }
                }
            }

            is Connection -> {
                stateFilter.reset() // the state message after a connection change goes to the kernel
                inKernel { onConnection(message) }
            }

            is Visualization -> message.agvPosition?.let { reports.pose(it.x, it.y, it.theta) }

            is JsonObject -> inKernel { factsheet = message }
        }
    }

    private fun inKernel(action: () -> Unit) = context.clock.schedule(0) {
        if (isEnabled) action()
    }

    private fun onConnection(message: Connection) {
        val previous = connectionState
        connectionState = message.connectionState
        if (previous == message.connectionState) return
        when (message.connectionState) {
            Vda.ONLINE -> {
                reports.state(VehicleState.IDLE)
                if (previous != "UNKNOWN") {
                    context.notifyUser(NotificationLevel.INFORMATIONAL, "VDA 5050 vehicle $vehicleName is online again")
                }
                sendInstantActions(listOf(Action(Vda.STATE_REQUEST, actions.newId(), "NONE"))) // resynchronise
            }

            else -> {
                reports.state(VehicleState.UNKNOWN)
                val holding = if (pendingCommands.isEmpty()) "" else KEEPS_RESOURCES
                context.notifyUser(
                    NotificationLevel.IMPORTANT,
                    "VDA 5050 vehicle $vehicleName is ${message.connectionState}$holding",
                )
            }
        }
        context.publishEvent("vda5050:connection", mapOf("state" to message.connectionState))
    }

    private fun onState(state: State) {
        if (connectionState == "UNKNOWN") connectionState = Vda.ONLINE
        reports.fromState(state)
        // The MQTT client may run the connection and state topics' callbacks on different threads: a state message sent
        // before the connection broke can arrive after the last will, and must not make the vehicle look present.
        reports.state(if (connectionState == Vda.ONLINE) state.vehicleState() else VehicleState.UNKNOWN)
        checkCancel(state)
        val rejection = state.errors.firstOrNull { it.errorType in Vda.REJECTIONS }
        if (rejection != null && order != null && ++rejections > properties.maxIgnoredRejections) {
            failOrder("the vehicle rejected the order: ${rejection.described()}")
            return
        }
        val fatal = state.errors.firstOrNull { it.errorLevel == Vda.FATAL }
        if (fatal != null && pendingCommands.isNotEmpty()) {
            failOrder("the vehicle reported an error: ${fatal.described()}")
            return
        }
        order?.let { current ->
            if (state.orderId == current.orderId) progress(current, state)
            resendIfLost(current, state)
        }
    }

    private fun progress(current: OrderTracker, state: State) {
        current.acknowledge(state.orderUpdateId)
        val nodes = state.nodeStates.map { it.sequenceId }.toSet()
        val edges = state.edgeStates.map { it.sequenceId }.toSet()
        val statuses = state.actionStates.associate { it.actionId to it }
        for (step in current.sent.toList()) {
            val final = step.command.finalMovement
            val edgeDone = step.edge == null || step.edge.sequenceId !in edges
            val nodeDone = step.node.sequenceId !in nodes
            val failed = step.actionIds.mapNotNull(statuses::get).firstOrNull { it.actionStatus == Vda.FAILED }
            if (failed != null) {
                val reason = failed.resultDescription ?: "no reason given"
                failOrder("action ${failed.actionType ?: failed.actionId} failed: $reason")
                return
            }
            val actionsDone = step.actionIds.all { statuses[it]?.actionStatus == Vda.FINISHED }
            val reached = !properties.lastNodeIdRequired || state.lastNodeSequenceId >= step.node.sequenceId
            val done = edgeDone && actionsDone && reached &&
                (nodeDone || (properties.completion == CompletionCondition.EDGE && !final))
            if (!done) break
            current.completed(step)
            onCommandExecuted(step.command)
        }
        if (current.unacknowledged == null) deferred.removeFirstOrNull()?.let(::release)
    }

    /**
     * The order topic is QoS 0 by default (openTCS's): an update the vehicle's state does not reflect a while after
     * it was sent is sent again (the vehicle ignores an update it already has).
     */
    private fun resendIfLost(current: OrderTracker, state: State) {
        val waiting = current.unacknowledged ?: return
        val reflected = state.orderId == waiting.orderId && state.orderUpdateId >= waiting.orderUpdateId
        if (!reflected && System.currentTimeMillis() - orderSentAt >= RESEND_MILLIS) publishOrder(waiting)
    }

    private fun checkCancel(state: State) {
        val cancel = pendingCancel ?: return
        val status = state.actionStates.firstOrNull { it.actionId == cancel.actionId }?.actionStatus
        if (status == null) {
            // Not reflected yet: lost on the way (QoS 0), so it goes again, as openTCS's driver does.
            if (System.currentTimeMillis() - cancelSentAt >= RESEND_MILLIS) {
                cancelSentAt = System.currentTimeMillis()
                sendInstantActions(listOf(cancel))
            }
            return
        }
        if (status == Vda.FINISHED || status == Vda.FAILED) {
            pendingCancel = null
            deferred.removeFirstOrNull()?.let(::release)
        }
    }

    private fun failOrder(reason: String) {
        log.warn("vehicle {}: {}", vehicleName, reason)
        context.setTransportOrderProperty(FAILURE_PROPERTY, reason)
        context.notifyUser(NotificationLevel.IMPORTANT, "VDA 5050 vehicle $vehicleName: $reason")
        rejections = 0
        val failed = pendingCommands.firstOrNull()
        cancelOrder()
        failed?.let { onCommandFailed(it, reason) }
    }

    companion object {
        const val INIT_POSITION = "vda5050:initPosition"
        const val STATE_REQUEST = "vda5050:stateRequest"
        const val FACTSHEET_REQUEST = "vda5050:factsheetRequest"
        const val START_PAUSE = "vda5050:startPause"
        const val STOP_PAUSE = "vda5050:stopPause"

        /** The transport-order property that says why the vehicle failed the order. */
        const val FAILURE_PROPERTY = "vda5050:failureReason"
        private const val RESEND_MILLIS = 2000L
        private const val KEEPS_RESOURCES = "; it keeps its allocated resources, as it is still physically there"
    }
}
