package org.ktcs.adapters.vda5050.broker

import io.netty.bootstrap.ServerBootstrap
import io.netty.buffer.Unpooled
import io.netty.channel.Channel
import io.netty.channel.ChannelInitializer
import io.netty.channel.MultiThreadIoEventLoopGroup
import io.netty.channel.nio.NioIoHandler
import io.netty.channel.socket.SocketChannel
import io.netty.channel.socket.nio.NioServerSocketChannel
import io.netty.handler.codec.mqtt.MqttDecoder
import io.netty.handler.codec.mqtt.MqttEncoder
import io.netty.util.concurrent.DefaultThreadFactory
import org.ktcs.adapters.vda5050.mqtt.BindCheck
import org.ktcs.adapters.vda5050.mqtt.MessageLink
import org.ktcs.extension.config.ConfigException
import org.slf4j.LoggerFactory
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.spi.SelectorProvider
import java.util.concurrent.TimeUnit

/**
 * kTCS's own MQTT broker (3.1.1 and 5), on Netty's MQTT codec and one event loop thread that owns all its state: the
 * vehicles connect to it over TCP, and the VDA 5050 driver is a [MessageLink] into it. The driver's listeners are
 * called on the event loop as a vehicle's message is read, without a thread hand-over and without a client round
 * trip; what the driver sends is routed like a message a client published. Wills and retained messages reach the
 * listeners too, so the driver needs no MQTT client.
 *
 * Sessions, subscriptions and retained messages live in memory and end with kTCS. Not supported: QoS 2 towards
 * subscribers (granted as QoS 1), redelivery of unacknowledged QoS 1 messages, queueing for offline persistent
 * sessions, MQTT 5's will delay, session expiry timing, topic aliases, shared subscriptions, subscription options
 * and identifiers, and enhanced authentication.
 */
class BuiltinBroker(private val config: BrokerConfig) : MessageLink, AutoCloseable {
    private val log = LoggerFactory.getLogger(BuiltinBroker::class.java)
    private val routing = Routing()
    private var group: MultiThreadIoEventLoopGroup? = null
    private var server: Channel? = null

    /** Starts listening; an address or port it cannot use is a [ConfigException] naming the setting. */
    fun start() {
        val address = BindCheck.check(config.bindAddress, config.port)
        val loop =
            MultiThreadIoEventLoopGroup(
                1,
                DefaultThreadFactory(THREAD_NAME, true),
                NioIoHandler.newFactory(SelectorProvider.provider(), BatchingSelect(config.batchMillis)),
            )
        val bound = ServerBootstrap().group(loop).channel(NioServerSocketChannel::class.java)
            .childHandler(initializer()).bind(InetSocketAddress(address, config.port)).awaitUninterruptibly()
        if (!bound.isSuccess) {
            loop.shutdownGracefully(0, 0, TimeUnit.SECONDS)
            throw ConfigException(
                "the embedded MQTT broker could not start on ${config.bindAddress}:${config.port} " +
                    "(${BindCheck.BIND_ADDRESS_KEY}, ${BindCheck.PORT_KEY}): ${bound.cause()?.message}",
            )
        }
        group = loop
        server = bound.channel()
        log.info("embedded MQTT broker (builtin) listening on {}:{}", config.bindAddress, config.port)
    }

    private fun initializer() = object : ChannelInitializer<SocketChannel>() {
        override fun initChannel(channel: SocketChannel) {
            val connection = ClientConnection(routing, config)
            channel.pipeline()
                .addLast("size-guard", PacketSizeGuard(config.maxPacketBytes) { _, size -> oversize(connection, size) })
                .addLast("decoder", MqttDecoder(config.maxPacketBytes, MAX_CLIENT_ID_LENGTH))
                .addLast("encoder", MqttEncoder.INSTANCE)
                .addLast("client", connection)
        }
    }

    private fun oversize(connection: ClientConnection, size: Long) =
        connection.close("sent a packet of $size bytes, over the maximum of ${config.maxPacketBytes}")

    /** How many PUBLISH packets the broker has received from its clients since it started. */
    fun publishesReceived(): Long = routing.publishesReceived

    /** Listens from when this returns; the topic's retained message (if any) is handed over first. */
    override fun listen(topic: String, qos: Int, handler: (ByteBuffer) -> Unit) = onLoopAndWait {
        routing.listen(topic, handler)
    }

    /** No message reaches the topic's handler after this returns. */
    override fun stopListening(topic: String) = onLoopAndWait { routing.stopListening(topic) }

    override fun send(topic: String, payload: ByteArray, qos: Int) = onLoop {
        routing.publish(topic, Unpooled.wrappedBuffer(payload), qos.coerceIn(0, 2), retain = false)
    }

    private fun onLoop(task: () -> Unit) {
        val loop = loop()
        if (loop.inEventLoop()) task() else loop.execute(task)
    }

    private fun onLoopAndWait(task: () -> Unit) {
        val loop = loop()
        if (loop.inEventLoop()) task() else loop.submit(task).syncUninterruptibly()
    }

    private fun loop() = checkNotNull(group) { "the embedded MQTT broker is not running" }.next()

    override fun close() {
        val loop = group ?: return
        group = null
        server?.close()?.awaitUninterruptibly()
        loop.shutdownGracefully(0, CLOSE_SECONDS, TimeUnit.SECONDS).awaitUninterruptibly()
        log.info("embedded MQTT broker stopped")
    }

    companion object {
        /** The prefix of the broker's event loop thread's name. */
        const val THREAD_NAME = "mqtt-broker"
        private const val MAX_CLIENT_ID_LENGTH = 65535
        private const val CLOSE_SECONDS = 5L
    }
}
