package org.ktcs.adapters.vda5050

import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import org.ktcs.adapters.vda5050.mqtt.MessageLink
import org.ktcs.adapters.vda5050.protocol.Action
import org.ktcs.adapters.vda5050.protocol.Checked
import org.ktcs.adapters.vda5050.protocol.Connection
import org.ktcs.adapters.vda5050.protocol.IncomingTopic
import org.ktcs.adapters.vda5050.protocol.InstantActions
import org.ktcs.adapters.vda5050.protocol.MessageValidator
import org.ktcs.adapters.vda5050.protocol.Order
import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.StateRead
import org.ktcs.adapters.vda5050.protocol.StateReader
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.adapters.vda5050.protocol.Vda5050Json
import org.ktcs.adapters.vda5050.protocol.Visualization
import org.slf4j.LoggerFactory
import java.nio.ByteBuffer
import java.time.Instant
import java.time.format.DateTimeFormatter
import java.util.concurrent.Executor
import java.util.concurrent.atomic.AtomicLong

/**
 * One VDA 5050 vehicle's topics under its `topicPrefix`: what the master control publishes (orders and instant
 * actions, with their header ids and timestamps) and what it listens to. The `connection` topic comes through
 * [connections], everything else through [messages] (the same MQTT client with an external broker; see
 * [Vda5050Broker]). An incoming message is validated against its schema (if `validateIncomingMessages`) and parsed on
 * the link's thread; an invalid or unreadable one is logged with the reason and dropped. Visualization messages within
 * `minVisualizationInterval` of the last one taken are dropped before their payload is read. Outgoing messages are
 * built, encoded and sent by [sending] (kTCS's sending thread, not the kernel's), in the order they were published.
 */
internal class VehicleTopics(
    private val vehicleName: String,
    private val properties: Vda5050Properties,
    private val messages: () -> MessageLink,
    private val connections: () -> MessageLink = messages,
    private val millis: () -> Long = System::currentTimeMillis,
    private val sending: Executor = Executor { it.run() },
) {
    // The driver's log category: what a user turns up to watch a vehicle's messages covers these lines too.
    private val log = LoggerFactory.getLogger(Vda5050Driver::class.java)
    private val headerIds = HashMap<String, Long>() // only on [sending]'s thread, one at a time

    // State messages repeat most of the last one: what they repeat is not checked and decoded again.
    private val states = StateReader(properties.validateIncomingMessages)

    @Volatile private var lastVisualizationMillis = Long.MIN_VALUE

    private val quickVisualization =
        if (properties.validateIncomingMessages) MessageValidator.quickSchema(IncomingTopic.VISUALIZATION) else null

    /** How many incoming messages were read (validated and parsed): dropped visualization messages are not. */
    val decoded = AtomicLong()

    /**
     * Listens to the vehicle's connection, state, visualization and factsheet topics; [received] gets a parsed
     * [Connection], [State], [Visualization] or factsheet [JsonObject].
     */
    fun listen(received: (Any) -> Unit) {
        val connection = properties.connection
        connections().listen(properties.topic(connection), connection.qos.coerceAtLeast(1)) { payload ->
            parsed(IncomingTopic.CONNECTION, payload)?.let(received)
        }
        val link = messages()
        listOf(
            properties.state to IncomingTopic.STATE,
            properties.visualization to IncomingTopic.VISUALIZATION,
            properties.factsheet to IncomingTopic.FACTSHEET,
        ).forEach { (topic, kind) ->
            link.listen(properties.topic(topic), topic.qos) { payload ->
                if (kind != IncomingTopic.VISUALIZATION || visualizationDue()) parsed(kind, payload)?.let(received)
            }
        }
        log.debug("vehicle {} listens on {}/#", vehicleName, properties.topicPrefix)
    }

    fun stopListening() {
        connections().stopListening(properties.topic(properties.connection))
        val link = messages()
        listOf(properties.state, properties.visualization, properties.factsheet)
            .forEach { link.stopListening(properties.topic(it)) }
    }

    // One link thread per vehicle at a time for an external broker, but the in-process link may use several.
    @Synchronized
    private fun visualizationDue(): Boolean {
        val now = millis()
        if (lastVisualizationMillis != Long.MIN_VALUE &&
            now - lastVisualizationMillis < properties.minVisualizationIntervalMillis
        ) {
            return false
        }
        lastVisualizationMillis = now
        return true
    }

    /** Publishes [update] as the next order message, encoded and sent by [sending]. */
    fun publishOrder(update: OrderUpdate) = sending.execute {
        val message = Order(
            nextHeader("order"), timestamp(), Vda.PROTOCOL_VERSION, properties.manufacturer, properties.serialNumber,
            update.orderId, update.orderUpdateId, update.nodes, update.edges,
        )
        publish(properties.order.name, properties.order.qos, Vda5050Json.encodeToString(Order.serializer(), message))
        log.debug("vehicle {}: order {} update {}", vehicleName, update.orderId, update.orderUpdateId)
    }

    /** Publishes [list] as the next instantActions message, encoded and sent by [sending]. */
    fun publishInstantActions(list: List<Action>) = sending.execute {
        val message = InstantActions(
            nextHeader("instantActions"),
            timestamp(),
            Vda.PROTOCOL_VERSION,
            properties.manufacturer,
            properties.serialNumber,
            list,
        )
        publish(
            properties.instantActions.name,
            properties.instantActions.qos,
            Vda5050Json.encodeToString(InstantActions.serializer(), message),
        )
    }

    private fun publish(topic: String, qos: Int, json: String) {
        messages().send("${properties.topicPrefix}/$topic", json.toByteArray(), qos)
    }

    private fun parsed(kind: IncomingTopic, payload: ByteBuffer): Any? {
        decoded.incrementAndGet()
        val bytes = ByteArray(payload.remaining()).also(payload::get)
        return try {
            if (kind == IncomingTopic.STATE) {
                when (val read = states.read(bytes)) {
                    is StateRead.Invalid -> invalid(kind, read.problems)
                    is StateRead.Valid -> read.state
                }
            } else if (kind == IncomingTopic.VISUALIZATION && quickVisualization?.accepts(bytes) == true) {
                // A plain pose, checked by its bytes: no tree to build, check and decode (several a second per vehicle).
                Vda5050Json.decodeFromString(Visualization.serializer(), String(bytes, Charsets.UTF_8))
            } else if (properties.validateIncomingMessages) {
                when (val checked = MessageValidator.check(kind, bytes)) {
                    is Checked.Invalid -> invalid(kind, checked.problems)
                    is Checked.Valid -> decode(kind, checked.json)
                }
            } else {
                decode(kind, Vda5050Json.parseToJsonElement(String(bytes, Charsets.UTF_8)))
            }
        } catch (error: SerializationException) {
            unreadable(kind, error)
        } catch (error: IllegalArgumentException) {
            unreadable(kind, error)
        }
    }

    private fun decode(kind: IncomingTopic, json: JsonElement): Any? = when (kind) {
        IncomingTopic.STATE -> Vda5050Json.decodeFromJsonElement(State.serializer(), json)
        IncomingTopic.CONNECTION -> Vda5050Json.decodeFromJsonElement(Connection.serializer(), json)
        IncomingTopic.VISUALIZATION -> Vda5050Json.decodeFromJsonElement(Visualization.serializer(), json)
        IncomingTopic.FACTSHEET -> json as? JsonObject
    }

    private fun invalid(kind: IncomingTopic, problems: List<String>): Nothing? {
        log.warn(
            "vehicle {}: dropped an invalid {} message: {}",
            vehicleName,
            kind.name.lowercase(),
            problems.take(MAX_PROBLEMS_LOGGED).joinToString("; "),
        )
        return null
    }

    private fun unreadable(kind: IncomingTopic, error: Exception): Nothing? {
        log.warn("vehicle {}: dropped an unreadable {} message: {}", vehicleName, kind.name.lowercase(), error.message)
        return null
    }

    private fun nextHeader(topic: String): Long = headerIds.merge(topic, 1L, Long::plus)!! - 1

    private fun timestamp(): String = DateTimeFormatter.ISO_INSTANT.format(Instant.now())

    private companion object {
        const val MAX_PROBLEMS_LOGGED = 5
    }
}
