package org.ktcs.adapters.vda5050.broker

import io.netty.buffer.ByteBuf
import io.netty.channel.ChannelFutureListener
import io.netty.channel.ChannelHandlerContext
import io.netty.channel.ChannelInboundHandlerAdapter
import io.netty.handler.codec.TooLongFrameException
import io.netty.handler.codec.mqtt.MqttConnectMessage
import io.netty.handler.codec.mqtt.MqttConnectReturnCode
import io.netty.handler.codec.mqtt.MqttFixedHeader
import io.netty.handler.codec.mqtt.MqttIdentifierRejectedException
import io.netty.handler.codec.mqtt.MqttMessage
import io.netty.handler.codec.mqtt.MqttMessageBuilders
import io.netty.handler.codec.mqtt.MqttMessageIdAndPropertiesVariableHeader
import io.netty.handler.codec.mqtt.MqttMessageIdVariableHeader
import io.netty.handler.codec.mqtt.MqttMessageType
import io.netty.handler.codec.mqtt.MqttProperties
import io.netty.handler.codec.mqtt.MqttPublishMessage
import io.netty.handler.codec.mqtt.MqttPublishVariableHeader
import io.netty.handler.codec.mqtt.MqttQoS
import io.netty.handler.codec.mqtt.MqttReasonCodeAndPropertiesVariableHeader
import io.netty.handler.codec.mqtt.MqttSubAckMessage
import io.netty.handler.codec.mqtt.MqttSubAckPayload
import io.netty.handler.codec.mqtt.MqttSubscribeMessage
import io.netty.handler.codec.mqtt.MqttUnacceptableProtocolVersionException
import io.netty.handler.codec.mqtt.MqttUnsubscribeMessage
import io.netty.handler.codec.mqtt.MqttVersion
import io.netty.handler.timeout.IdleStateEvent
import io.netty.handler.timeout.IdleStateHandler
import io.netty.util.ReferenceCountUtil
import org.slf4j.LoggerFactory
import java.util.concurrent.TimeUnit

/**
 * One client's connection to the builtin broker, on the broker's event loop: its CONNECT, what it publishes and
 * subscribes to, its keep-alive and its will. A packet the codec cannot read, or one that breaks the protocol, closes
 * this connection with a log line and harms nothing else.
 */
internal class ClientConnection(private val routing: Routing, private val config: BrokerConfig) :
    ChannelInboundHandlerAdapter() {
    private val log = LoggerFactory.getLogger(BuiltinBroker::class.java)
    private lateinit var context: ChannelHandlerContext
    private var session: Session? = null
    private var v5 = false
    private var will: Will? = null
    private var nextPacketId = 0
    private val awaitingRelease = HashSet<Int>() // QoS 2 packet ids received, not yet released

    /** Who this is in log lines: the client id once known, and the address. */
    val name: String get() = "'${session?.clientId ?: "?"}' (${context.channel().remoteAddress()})"

    override fun handlerAdded(ctx: ChannelHandlerContext) {
        context = ctx
    }

    override fun channelRead(ctx: ChannelHandlerContext, msg: Any) {
        try {
            val message = msg as MqttMessage
            if (message.decoderResult().isFailure) badPacket(message) else handle(message)
        } finally {
            ReferenceCountUtil.release(msg)
        }
    }

    private fun handle(message: MqttMessage) {
        val type = message.fixedHeader().messageType()
        if (type == MqttMessageType.CONNECT) return connect(message as MqttConnectMessage)
        val current = session ?: return close("sent $type before CONNECT")
        when (type) {
            MqttMessageType.PUBLISH -> publish(message as MqttPublishMessage)
            MqttMessageType.PUBREL -> released(packetId(message))
            MqttMessageType.PUBACK, MqttMessageType.PUBREC, MqttMessageType.PUBCOMP -> Unit
            MqttMessageType.SUBSCRIBE -> subscribe(current, message as MqttSubscribeMessage)
            MqttMessageType.UNSUBSCRIBE -> unsubscribe(current, message as MqttUnsubscribeMessage)
            MqttMessageType.PINGREQ -> context.writeAndFlush(MqttMessage.PINGRESP, context.voidPromise())
            MqttMessageType.DISCONNECT -> disconnect(message)
            else -> close("sent a $type packet, which a client does not send")
        }
    }

    private fun connect(connect: MqttConnectMessage) {
        if (session != null) return close("sent a second CONNECT")
        val header = connect.variableHeader()
        v5 = header.version() == MqttVersion.MQTT_5.protocolLevel().toInt()
        ConnectAnswer.refusal(connect, config.username, config.password)?.let { return refuse(it) }
        val given = connect.payload().clientIdentifier().orEmpty()
        val clientId = given.ifEmpty { "ktcs-assigned-${System.nanoTime()}" }
        val persistent = if (v5) sessionExpiry(connect) > 0 else !header.isCleanSession
        val willTopic = connect.payload().willTopic()
        if (header.isWillFlag && (willTopic == null || !TopicNames.isValidName(willTopic))) {
            return close("sent a will topic that is not a valid topic name: '$willTopic'")
        }
        val (attached, present) = routing.attach(clientId, this, header.isCleanSession, persistent)
        session = attached
        will = Will.of(connect)
        watchKeepAlive(header.keepAliveTimeSeconds())
        val connAck = MqttMessageBuilders.connAck()
            .returnCode(MqttConnectReturnCode.CONNECTION_ACCEPTED)
            .sessionPresent(present)
        if (v5) connAck.properties(connAckProperties(assignedId = clientId.takeIf { given.isEmpty() }))
        context.writeAndFlush(connAck.build(), context.voidPromise())
        log.debug("MQTT client {} connected", name)
    }

    private fun sessionExpiry(connect: MqttConnectMessage): Int =
        (connect.variableHeader().properties().getProperty(SESSION_EXPIRY)?.value() as? Int) ?: 0

    private fun connAckProperties(assignedId: String?): MqttProperties {
        val properties = MqttMessageBuilders.ConnAckPropertiesBuilder()
            .maximumPacketSize(config.maxPacketBytes.toLong())
            .sharedSubscriptionAvailable(false)
            .subscriptionIdentifiersAvailable(false)
            .topicAliasMaximum(0)
        assignedId?.let { properties.assignedClientId(it) }
        return properties.build()
    }

    // MQTT: a client silent for 1.5 times its keep-alive is gone.
    private fun watchKeepAlive(seconds: Int) {
        if (seconds <= 0) return
        val millis = seconds * KEEP_ALIVE_GRACE_MILLIS
        context.pipeline().addBefore(
            context.name(),
            "keep-alive",
            IdleStateHandler(millis, 0, 0, TimeUnit.MILLISECONDS),
        )
    }

    private fun refuse(code: MqttConnectReturnCode) {
        log.info("MQTT client at {} refused: {}", context.channel().remoteAddress(), code)
        val connAck = MqttMessageBuilders.connAck().returnCode(code).sessionPresent(false).build()
        context.writeAndFlush(connAck).addListener(ChannelFutureListener.CLOSE)
    }

    private fun publish(message: MqttPublishMessage) {
        val header = message.variableHeader()
        val topic = header.topicName()
        if (topic == null || !TopicNames.isValidName(topic)) {
            return close("published to '$topic', which is not a topic name (topic aliases are not supported)")
        }
        val qos = message.fixedHeader().qosLevel().value()
        val packetId = header.packetId()
        when (qos) {
            0 -> routing.received(topic, message.payload(), 0, message.fixedHeader().isRetain)

            1 -> {
                routing.received(topic, message.payload(), 1, message.fixedHeader().isRetain)
                reply(MqttMessageType.PUBACK, packetId)
            }

            else -> {
                // Exactly once: a repeated packet id before its PUBREL is the same message again.
                if (awaitingRelease.add(
                        packetId,
                    )
                ) {
                    routing.received(topic, message.payload(), 2, message.fixedHeader().isRetain)
                }
                reply(MqttMessageType.PUBREC, packetId)
            }
        }
    }

    private fun released(packetId: Int) {
        awaitingRelease.remove(packetId)
        reply(MqttMessageType.PUBCOMP, packetId)
    }

    private fun reply(type: MqttMessageType, packetId: Int) {
        val fixed = MqttFixedHeader(type, false, MqttQoS.AT_MOST_ONCE, false, 2)
        context.writeAndFlush(MqttMessage(fixed, MqttMessageIdVariableHeader.from(packetId)), context.voidPromise())
    }

    private fun packetId(message: MqttMessage): Int = when (val header = message.variableHeader()) {
        is MqttMessageIdVariableHeader -> header.messageId()
        else -> 0
    }

    private fun subscribe(session: Session, message: MqttSubscribeMessage) {
        val requests = message.payload().topicSubscriptions()
        val codes = requests.map { request ->
            val filter = request.topicFilter()
            when {
                filter.startsWith(SHARED_PREFIX) -> if (v5) SHARED_NOT_SUPPORTED else FAILURE

                !TopicNames.isValidFilter(filter) -> if (v5) FILTER_INVALID else FAILURE

                else -> minOf(request.qualityOfService().value(), MAX_QOS).also {
                    routing.subscribe(session, filter, it)
                }
            }
        }
        val subAck = MqttSubAckMessage(
            MqttFixedHeader(MqttMessageType.SUBACK, false, MqttQoS.AT_MOST_ONCE, false, 0),
            MqttMessageIdAndPropertiesVariableHeader(
                message.variableHeader().messageId(),
                MqttProperties.NO_PROPERTIES,
            ),
            MqttSubAckPayload(*codes.toIntArray()),
        )
        context.writeAndFlush(subAck, context.voidPromise())
        requests.zip(codes).filter { (_, code) -> code <= MAX_QOS }.forEach { (request, granted) ->
            routing.retainedFor(request.topicFilter()).forEach {
                send(it.topic, Routing.payloadOf(it.payload), minOf(it.qos, granted), retain = true)
            }
        }
    }

    private fun unsubscribe(session: Session, message: MqttUnsubscribeMessage) {
        val codes = message.payload().topics().map {
            if (routing.unsubscribe(session, it)) SUCCESS else NO_SUBSCRIPTION
        }
        val unsubAck = MqttMessageBuilders.unsubAck().packetId(message.variableHeader().messageId())
        if (v5) unsubAck.addReasonCodes(*codes.toTypedArray())
        context.writeAndFlush(unsubAck.build(), context.voidPromise())
    }

    private fun disconnect(message: MqttMessage) {
        val reason = (message.variableHeader() as? MqttReasonCodeAndPropertiesVariableHeader)?.reasonCode()
        if (reason != Will.DISCONNECT_WITH_WILL) will = null
        context.close()
    }

    /**
     * Sends a message to the client; [payload] stays the caller's. A QoS 0 message to a client that does not read
     * fast enough is dropped rather than queued without limit.
     */
    fun send(topic: String, payload: ByteBuf, qos: Int, retain: Boolean) {
        val channel = context.channel()
        if (!channel.isActive || (qos == 0 && !channel.isWritable)) return
        val packetId = if (qos > 0) nextPacketId() else 0
        val fixed = MqttFixedHeader(MqttMessageType.PUBLISH, false, MqttQoS.valueOf(qos), retain, 0)
        val message = MqttPublishMessage(fixed, MqttPublishVariableHeader(topic, packetId), payload.retainedDuplicate())
        context.writeAndFlush(message, context.voidPromise())
    }

    private fun nextPacketId(): Int {
        nextPacketId = nextPacketId % MAX_PACKET_ID + 1
        return nextPacketId
    }

    /** Another connection took this one's client id: the will goes out now, before the new connection's messages. */
    fun takenOver() {
        log.info("MQTT client {} taken over by a new connection with its client id", name)
        publishWill()
        session = null
        if (v5) {
            val header = MqttReasonCodeAndPropertiesVariableHeader(SESSION_TAKEN_OVER, MqttProperties.NO_PROPERTIES)
            val disconnect =
                MqttMessage(MqttFixedHeader(MqttMessageType.DISCONNECT, false, MqttQoS.AT_MOST_ONCE, false, 0), header)
            context.writeAndFlush(disconnect).addListener(ChannelFutureListener.CLOSE)
        } else {
            context.close()
        }
    }

    override fun userEventTriggered(ctx: ChannelHandlerContext, event: Any) {
        if (event is IdleStateEvent) {
            close("sent nothing for 1.5 times its keep-alive")
        } else {
            ctx.fireUserEventTriggered(event)
        }
    }

    override fun channelInactive(ctx: ChannelHandlerContext) {
        val current = session ?: return
        publishWill()
        routing.detach(current, this)
        session = null
        log.debug("MQTT client {} disconnected", name)
    }

    override fun exceptionCaught(ctx: ChannelHandlerContext, cause: Throwable) {
        close("failed: $cause")
    }

    private fun publishWill() {
        val last = will ?: return
        will = null
        routing.publish(last.topic, Routing.payloadOf(last.payload), last.qos, last.retain)
    }

    private fun badPacket(message: MqttMessage) {
        when (val cause = message.decoderResult().cause()) {
            is MqttUnacceptableProtocolVersionException -> refuse(ConnectAnswer.unsupportedProtocol(v5))

            is MqttIdentifierRejectedException -> refuse(ConnectAnswer.badClientId(v5))

            is TooLongFrameException -> close(
                "sent a packet over the maximum of ${config.maxPacketBytes} bytes (${cause.message})",
            )

            else -> close("sent a malformed packet: ${cause.message}")
        }
    }

    /** Closes the connection for what the client did (a protocol error: its will is published). */
    fun close(why: String) {
        log.warn("MQTT client {} {}: connection closed", name, why)
        context.close()
    }

    private companion object {
        const val KEEP_ALIVE_GRACE_MILLIS = 1500L
        const val MAX_QOS = 1
        const val FAILURE = 0x80
        const val FILTER_INVALID = 0x8F
        const val SHARED_NOT_SUPPORTED = 0x9E
        const val SUCCESS: Short = 0x00
        const val NO_SUBSCRIPTION: Short = 0x11
        const val SESSION_TAKEN_OVER: Byte = 0x8E.toByte()
        const val SHARED_PREFIX = "\$share/"
        const val MAX_PACKET_ID = 65535
        val SESSION_EXPIRY = MqttProperties.MqttPropertyType.SESSION_EXPIRY_INTERVAL.value()
    }
}
