package org.ktcs.adapters.vda5050.broker

import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.MqttGlobalPublishFilter
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.exceptions.Mqtt3ConnAckException
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import com.hivemq.client.mqtt.mqtt5.Mqtt5BlockingClient
import com.hivemq.client.mqtt.mqtt5.exceptions.Mqtt5ConnAckException
import com.hivemq.client.mqtt.mqtt5.message.connect.connack.Mqtt5ConnAckReasonCode
import com.hivemq.client.mqtt.mqtt5.message.subscribe.suback.Mqtt5SubAckReasonCode
import io.kotest.assertions.nondeterministic.eventually
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.netty.buffer.Unpooled
import io.netty.handler.codec.mqtt.MqttMessage
import io.netty.handler.codec.mqtt.MqttMessageBuilders
import io.netty.handler.codec.mqtt.MqttQoS
import org.ktcs.adapters.vda5050.freePort
import org.slf4j.LoggerFactory
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.seconds

/** kTCS's builtin broker against real MQTT 5 and 3.1.1 clients (HiveMQ's), and against raw bytes. */
class BuiltinBrokerTest : FunSpec({
    val port = freePort()
    val broker = BuiltinBroker(BrokerConfig(port = port, maxPacketBytes = MAX_PACKET))
    val securedPort = freePort()
    val secured = BuiltinBroker(BrokerConfig(port = securedPort, username = "fleet", password = "secret"))
    val logged = ListAppender<ILoggingEvent>().apply { start() }
    beforeSpec {
        broker.start()
        secured.start()
        (LoggerFactory.getLogger(BuiltinBroker::class.java) as Logger).addAppender(logged)
    }
    afterSpec {
        (LoggerFactory.getLogger(BuiltinBroker::class.java) as Logger).detachAppender(logged)
        broker.close()
        secured.close()
    }

    fun v5(id: String, brokerPort: Int = port): Mqtt5BlockingClient = MqttClient.builder().useMqttVersion5()
        .identifier(id).serverHost("127.0.0.1").serverPort(brokerPort).buildBlocking()

    fun v3(id: String, brokerPort: Int = port) = MqttClient.builder().useMqttVersion3()
        .identifier(id).serverHost("127.0.0.1").serverPort(brokerPort).buildBlocking()

    fun Mqtt5BlockingClient.Mqtt5Publishes.next(): String? =
        receive(2, TimeUnit.SECONDS).map { String(it.payloadAsBytes) }.orElse(null)

    fun logLines() = logged.list.map { it.formattedMessage }

    test("wildcards: + matches one level, # the rest and its parent; neither matches a \$ topic") {
        val subscriber = v5("wild-sub").apply { connect() }
        val publishes = subscriber.publishes(MqttGlobalPublishFilter.ALL)
        val ack = subscriber.subscribeWith().topicFilter("w/+/state").qos(MqttQos.AT_LEAST_ONCE).send()
        ack.reasonCodes shouldContainExactly listOf(Mqtt5SubAckReasonCode.GRANTED_QOS_1)
        subscriber.subscribeWith().topicFilter("x/#").send()
        subscriber.subscribeWith().topicFilter("+/dollar").send()
        val publisher = v3("wild-pub").apply { connect() }
        listOf("w/1/state", "w/1/2/state", "x", "x/y/z", "\$SYS/dollar", "w/2/state").forEach {
            publisher.publishWith().topic(it).payload(it.toByteArray()).send()
        }
        listOf(publishes.next(), publishes.next(), publishes.next(), publishes.next()) shouldContainExactly
            listOf("w/1/state", "x", "x/y/z", "w/2/state")
        publishes.next() shouldBe null
        subscriber.disconnect()
        publisher.disconnect()
    }

    test("a bad filter gets a failure in the SUBACK, the good ones beside it are granted (QoS 2 as 1)") {
        RawClient(port).use { client ->
            client.write(RawClient.connect("filters"))
            client.read(4)
            val subscribe = MqttMessageBuilders.subscribe().messageId(5)
                .addSubscription(
                    MqttQoS.EXACTLY_ONCE,
                    "ok/#",
                ).addSubscription(MqttQoS.AT_MOST_ONCE, "bad/#/more").build()
            client.write(subscribe)
            client.read(6) shouldBe byteArrayOf(0x90.toByte(), 4, 0, 5, 1, 0x80.toByte())
        }
    }

    test("retained messages: set, replaced, delivered on subscribe with the retain flag, cleared by an empty one") {
        val publisher = v5("retain-pub").apply { connect() }
        publisher.publishWith().topic("r/1").payload("first".toByteArray()).retain(true).send()
        publisher.publishWith().topic("r/1").payload("second".toByteArray()).retain(true).send()
        val late = v5("retain-late").apply { connect() }
        val publishes = late.publishes(MqttGlobalPublishFilter.ALL)
        late.subscribeWith().topicFilter("r/+").send()
        val retained = publishes.receive(2, TimeUnit.SECONDS).get()
        String(retained.payloadAsBytes) shouldBe "second"
        retained.isRetain shouldBe true
        publisher.publishWith().topic("r/1").payload(ByteArray(0)).retain(true).send()
        publishes.receive(2, TimeUnit.SECONDS).get().isRetain shouldBe false // live: the flag is cleared
        val later = v5("retain-later").apply { connect() }
        val laterPublishes = later.publishes(MqttGlobalPublishFilter.ALL)
        later.subscribeWith().topicFilter("r/1").send()
        laterPublishes.next() shouldBe null
        listOf(publisher, late, later).forEach { it.disconnect() }
    }

    test("a dropped connection's retained will is published; a DISCONNECT's is not") {
        val watcher = v5("will-watch").apply { connect() }
        val publishes = watcher.publishes(MqttGlobalPublishFilter.ALL)
        watcher.subscribeWith().topicFilter("will/+").send()
        RawClient(port).use { vehicle ->
            vehicle.write(RawClient.connect("will-drop", willTopic = "will/drop", will = "CONNECTIONBROKEN"))
            vehicle.read(4) shouldBe byteArrayOf(0x20, 2, 0, 0)
        }
        publishes.next() shouldBe "CONNECTIONBROKEN"
        RawClient(port).use { vehicle ->
            vehicle.write(RawClient.connect("will-clean", willTopic = "will/clean", will = "unexpected"))
            vehicle.read(4)
            vehicle.write(MqttMessage.DISCONNECT)
            vehicle.closedByBroker() shouldBe true
        }
        publishes.next() shouldBe null
        val late = v5("will-late").apply { connect() }
        val latePublishes = late.publishes(MqttGlobalPublishFilter.ALL)
        late.subscribeWith().topicFilter("will/drop").send()
        latePublishes.receive(2, TimeUnit.SECONDS).get().isRetain shouldBe true
        watcher.disconnect()
        late.disconnect()
    }

    test("a client silent for 1.5 times its keep-alive is closed and its will published") {
        val watcher = v5("keepalive-watch").apply { connect() }
        val publishes = watcher.publishes(MqttGlobalPublishFilter.ALL)
        watcher.subscribeWith().topicFilter("silent/connection").send()
        RawClient(port).use { vehicle ->
            val started = System.nanoTime()
            vehicle.write(
                RawClient.connect("silent", keepAliveSeconds = 1, willTopic = "silent/connection", will = "gone"),
            )
            vehicle.read(4)
            vehicle.closedByBroker() shouldBe true
            val seconds = (System.nanoTime() - started) / 1e9
            (seconds in 1.4..4.0) shouldBe true
        }
        publishes.next() shouldBe "gone"
        logLines().any { it.contains("'silent'") && it.contains("keep-alive") } shouldBe true
        watcher.disconnect()
    }

    test("a second connection with the same client id takes the session over; the first is closed") {
        val first = v5("same-id").apply { connect() }
        val second = v5("same-id").apply { connect() }
        eventually(5.seconds) { first.state.isConnected shouldBe false }
        second.state.isConnected shouldBe true
        val publishes = second.publishes(MqttGlobalPublishFilter.ALL)
        second.subscribeWith().topicFilter("takeover").send()
        v3("takeover-pub").apply { connect() }.publishWith().topic("takeover").payload("hello".toByteArray()).send()
        publishes.next() shouldBe "hello"
        second.disconnect()
    }

    test("a persistent session keeps its subscriptions while the client is away (session present)") {
        val client = v3("persistent")
        client.connectWith().cleanSession(false).send().isSessionPresent shouldBe false
        client.subscribeWith().topicFilter("kept").qos(MqttQos.AT_LEAST_ONCE).send()
        client.disconnect()
        client.connectWith().cleanSession(false).send().isSessionPresent shouldBe true
        client.disconnect()
        client.connectWith().cleanSession(true).send().isSessionPresent shouldBe false
        client.disconnect()
    }

    test("a QoS 1 PUBLISH is answered with a PUBACK of its packet id; QoS 2 with PUBREC and PUBCOMP") {
        RawClient(port).use { client ->
            client.write(RawClient.connect("qos"))
            client.read(4)
            client.write(publish("q/1", 1, 7, "x".toByteArray()))
            client.read(4) shouldBe byteArrayOf(0x40, 2, 0, 7)
            client.write(publish("q/2", 2, 8, "y".toByteArray()))
            client.read(4) shouldBe byteArrayOf(0x50, 2, 0, 8)
            client.write(byteArrayOf(0x62, 2, 0, 8)) // PUBREL
            client.read(4) shouldBe byteArrayOf(0x70, 2, 0, 8)
            client.write(byteArrayOf(0xC0.toByte(), 0)) // PINGREQ
            client.read(2) shouldBe byteArrayOf(0xD0.toByte(), 0)
        }
    }

    test("an oversize packet closes its connection with a log line naming the client and the size") {
        RawClient(port).use { client ->
            client.write(RawClient.connect("big"))
            client.read(4)
            client.write(publish("big", 0, 0, ByteArray(MAX_PACKET * 2)))
            client.closedByBroker() shouldBe true
        }
        logLines().any { it.contains("'big'") && it.contains("${MAX_PACKET * 2 + 5} bytes") } shouldBe true
        v5("after-big").apply { connect() }.disconnect() // nothing else harmed
    }

    test("a malformed packet closes its connection with a log line") {
        RawClient(port).use { client ->
            client.write(RawClient.connect("malformed"))
            client.read(4)
            client.write(byteArrayOf(0x00, 0x00)) // packet type 0 is reserved
            client.closedByBroker() shouldBe true
        }
        logLines().any { it.contains("'malformed'") && it.contains("malformed packet") } shouldBe true
        RawClient(port).use { client ->
            client.write(publish("early", 0, 0, "x".toByteArray()))
            client.closedByBroker() shouldBe true
        }
    }

    test("bad CONNECTs: an unknown protocol level, an empty id without a clean session, wrong credentials") {
        RawClient(port).use { client ->
            // CONNECT, protocol name "MQTT", level 9, clean session, keep-alive 60, empty client id
            client.write(byteArrayOf(0x10, 12, 0, 4) + "MQTT".toByteArray() + byteArrayOf(9, 2, 0, 60, 0, 0))
            client.read(4) shouldBe byteArrayOf(0x20, 2, 0, 1)
            client.closedByBroker() shouldBe true
        }
        RawClient(port).use { client ->
            client.write(RawClient.connect("", cleanSession = false))
            client.read(4) shouldBe byteArrayOf(0x20, 2, 0, 2)
        }
        val v3Refused = shouldThrow<Mqtt3ConnAckException> {
            v3("intruder", securedPort).connectWith().simpleAuth().username("fleet").password("guess".toByteArray())
                .applySimpleAuth().send()
        }
        v3Refused.mqttMessage.returnCode shouldBe Mqtt3ConnAckReturnCode.BAD_USER_NAME_OR_PASSWORD
        val v5Refused = shouldThrow<Mqtt5ConnAckException> { v5("anonymous", securedPort).connect() }
        v5Refused.mqttMessage.reasonCode shouldBe Mqtt5ConnAckReasonCode.BAD_USER_NAME_OR_PASSWORD
        val allowed = v5("fleet-member", securedPort)
        allowed.connectWith().simpleAuth().username("fleet").password("secret".toByteArray()).applySimpleAuth().send()
        allowed.disconnect()
    }

    test("an MQTT 5 client without an id gets one assigned") {
        val client = MqttClient.builder().useMqttVersion5().serverHost("127.0.0.1").serverPort(port).buildBlocking()
        client.connect().assignedClientIdentifier.isPresent shouldBe true
        client.disconnect()
    }

    test("in process: a listener hears its topic's retained message and every message after, wills too") {
        val heard = java.util.Collections.synchronizedList(mutableListOf<String>())
        val vehicle = v3("in-process-vehicle").apply { connect() }
        vehicle.publishWith().topic("ip/connection").payload("ONLINE".toByteArray()).retain(true).send()
        eventually(5.seconds) {
            broker.listen("ip/connection", 1) { heard += Charsets.UTF_8.decode(it).toString() }
            heard.toList() shouldContainExactly listOf("ONLINE")
        }
        broker.listen("ip/state", 0) { heard += Charsets.UTF_8.decode(it).toString() }
        vehicle.publishWith().topic("ip/state").payload("state".toByteArray()).send()
        eventually(5.seconds) { heard.last() shouldBe "state" }
        val orders = vehicle.publishes(MqttGlobalPublishFilter.ALL)
        vehicle.subscribeWith().topicFilter("ip/order").send()
        broker.send("ip/order", "order".toByteArray(), 1)
        String(orders.receive(2, TimeUnit.SECONDS).get().payloadAsBytes) shouldContain "order"
        vehicle.disconnect()
    }
}) {
    private companion object {
        const val MAX_PACKET = 1024

        fun publish(topic: String, qos: Int, packetId: Int, payload: ByteArray) = RawClient.encode(
            MqttMessageBuilders.publish().topicName(topic).qos(MqttQoS.valueOf(qos)).messageId(packetId)
                .payload(Unpooled.wrappedBuffer(payload)).build(),
        )
    }
}
