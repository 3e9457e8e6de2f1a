package org.ktcs.kernel.bench

import kotlinx.serialization.json.JsonPrimitive
import org.ktcs.kernel.bench.WatchedMessage.Observed
import java.net.http.WebSocket
import java.nio.CharBuffer
import java.util.concurrent.CompletionStage
import java.util.concurrent.TimeUnit

/**
 * Follows kTCS's WebSocket (`/v1/ws`: vehicles, transport orders, notifications) and keeps what the batch workload
 * reports: each order's state and when it became dispatchable and was assigned, deadlock notifications, and every
 * moment in which a resource was allocated to two vehicles or two vehicles stood on one point, checked after each
 * vehicle event in kernel order.
 */
class EventWatcher(client: BenchClient) : AutoCloseable {
    private val lock = Object()
    private val orderStates = HashMap<String, String>()
    private val dispatchableAt = HashMap<String, Long>()
    private val assignLatencies = ArrayList<Double>()
    private val finalAt = HashMap<String, Long>()
    private val fleet = FleetConflicts()
    private val allocatedSteps = HashMap<String, List<List<String>>>()
    private var deadlocks = 0
    private var idleVehiclesMoved = 0
    private var missed = 0
    private val eventCounts = HashMap<String, Int>()
    private var eventChars = 0L
    private val text = StringBuilder()
    private val socket: WebSocket = client.httpClient().newWebSocketBuilder()
        .buildAsync(client.webSocketUri(), Listener())
        .get(CONNECT_SECONDS, TimeUnit.SECONDS)
        .also { it.sendText(SUBSCRIPTION, true) }

    /** The states of the orders whose names start with [prefix]. */
    fun states(
        prefix: String,
    ): Map<String, String> = synchronized(lock) { orderStates.filterKeys { it.startsWith(prefix) } }

    fun assignLatenciesMillis(): List<Double> = synchronized(lock) { assignLatencies.toList() }

    /** When ([System.nanoTime]) each order whose name starts with [prefix] and that is final became so. */
    fun finalTimes(prefix: String): List<Long> =
        synchronized(lock) { finalAt.filterKeys { it.startsWith(prefix) }.values.toList() }

    fun doubleAllocations(): Int = synchronized(lock) { fleet.doubleAllocations() }

    fun sharedPositions(): Int = synchronized(lock) { fleet.sharedPositions() }

    /** Notifications of deadlocks: vehicles that waited for each other, found by the watchdog. */
    fun deadlockNotifications(): Int = synchronized(lock) { deadlocks }

    /**
     * The watchdog's other notifications: an idle vehicle in another's way sent off it. No deadlock (the idle vehicle
     * waits for nothing), but the watchdog acting all the same.
     */
    fun idleVehicleNotifications(): Int = synchronized(lock) { idleVehiclesMoved }

    /** How often kTCS said the bench fell behind and sent fresh snapshots (latencies of those moments are lost). */
    fun missedEvents(): Int = synchronized(lock) { missed }

    /** How many events of each topic came, e.g. to see what the stream costs per finished order. */
    fun eventCounts(): Map<String, Int> = synchronized(lock) { eventCounts.toMap() }

    /** The characters of all the events that came (their JSON text). */
    fun eventChars(): Long = synchronized(lock) { eventChars }

    override fun close() {
        runCatching { socket.sendClose(WebSocket.NORMAL_CLOSURE, "done").get(CONNECT_SECONDS, TimeUnit.SECONDS) }
        socket.abort()
    }

    private fun onMessage(message: WatchedMessage) = synchronized(lock) {
        when (message.type) {
            "snapshot" -> onSnapshot(message.topic, message.objects)
            "event" -> update(message.topic, message.current, message.previous, message.shortened)
            "missed" -> missed++
        }
    }

    /**
     * A snapshot replaces what the bench knew of its topic all at once: checking its vehicles one by one against
     * the others' older state would report conflicts that never existed.
     */
    private fun onSnapshot(topic: String?, objects: List<Observed>) {
        if (topic != "vehicles") return objects.forEach { update(topic, it, null, emptyMap()) }
        allocatedSteps.clear()
        fleet.snapshot(
            objects.mapNotNull { vehicle ->
                val name = vehicle.name ?: return@mapNotNull null
                val steps = vehicle.allocatedResources.orEmpty().also { allocatedSteps[name] = it }
                FleetConflicts.Standing(name, steps.flatten().toSet(), vehicle.point)
            },
        )
    }

    private fun update(topic: String?, current: Observed?, previous: Observed?, shortened: Map<String, Int>) {
        when (topic) {
            "transportOrders" -> current?.let(::onOrder)
            "vehicles" -> current?.let { onVehicle(it, shortened["allocatedResources"]) }
            "notifications" -> if (previous == null && current != null) onNotification(current)
        }
    }

    private fun onOrder(order: Observed) {
        val name = order.name ?: return
        val state = (order.state as? JsonPrimitive)?.takeIf { it.isString }?.content ?: return
        val before = orderStates.put(name, state)
        if (state == before) return
        val now = System.nanoTime()
        when (state) {
            "DISPATCHABLE" -> dispatchableAt[name] = now

            "BEING_PROCESSED" -> dispatchableAt.remove(name)?.let {
                assignLatencies +=
                    (now - it) / OrderPosting.NANOS_PER_MILLI
            }

            in OrderPosting.FINAL_STATES -> finalAt.putIfAbsent(name, now)
        }
    }

    /** A vehicle's change; [dropped] steps of its allocations were passed (said instead of sending the rest). */
    private fun onVehicle(vehicle: Observed, dropped: Int?) {
        val name = vehicle.name ?: return
        // Left out as unchanged (the subscription asks for that), the resources and the point are the vehicle's before.
        val before = allocatedSteps[name].orEmpty()
        val steps = vehicle.allocatedResources ?: dropped?.let { before.drop(it) } ?: before
        if (steps !== before) allocatedSteps[name] = steps
        val held = if (steps === before) fleet.held(name) else steps.flatten().toSet()
        val point = if (vehicle.sendsPosition) vehicle.point else fleet.position(name)
        fleet.vehicle(FleetConflicts.Standing(name, held, point))
    }

    private fun count(message: WatchedMessage, chars: Int) = synchronized(lock) {
        if (message.type != "event") return
        eventCounts.merge(message.topic ?: "?", 1, Int::plus)
        eventChars += chars
    }

    private fun onNotification(notification: Observed) {
        when {
            notification.isDeadlock -> deadlocks++
            notification.isIdleVehicleMoved -> idleVehiclesMoved++
        }
    }

    private inner class Listener : WebSocket.Listener {
        override fun onText(webSocket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
            if (!last) {
                appendTo(text, data)
            } else {
                val message = if (text.isEmpty()) data.toString() else appendTo(text, data).toString()
                text.setLength(0)
                WatchedMessage.parse(message)?.let {
                    count(it, message.length)
                    onMessage(it)
                }
            }
            webSocket.request(1)
            return null
        }
    }

    private companion object {
        const val CONNECT_SECONDS = 10L

        /**
         * The JDK hands a message's text over as a [CharBuffer]; `StringBuilder.append(CharSequence)` copies that one
         * `charAt` at a time, which was a quarter of the bench's CPU in a large run (CPU that kTCS, on the same cores,
         * did not get). Its backing array is copied in bulk.
         */
        fun appendTo(text: StringBuilder, data: CharSequence): StringBuilder {
            if (data is CharBuffer && data.hasArray()) {
                text.append(data.array(), data.arrayOffset() + data.position(), data.remaining())
            } else {
                text.append(data)
            }
            return text
        }

        // As the browser overview subscribes: only a removed object's previous state, only the fields that changed,
        // resource lists that lost their first steps as the number lost.
        const val SUBSCRIPTION =
            """{"type":"subscribe","topics":["vehicles","transportOrders","notifications"],"previous":false,""" +
                """"onlyChanged":true,"shortenedLists":true}"""
    }
}
