package org.ktcs.adapters.vda5050.bench

import com.hivemq.embedded.EmbeddedExtension
import com.hivemq.extension.sdk.api.ExtensionMain
import com.hivemq.extension.sdk.api.interceptor.publish.PublishInboundInterceptor
import com.hivemq.extension.sdk.api.parameter.ExtensionStartInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStartOutput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopOutput
import com.hivemq.extension.sdk.api.services.Services
import org.ktcs.adapters.vda5050.broker.BrokerConfig
import org.ktcs.adapters.vda5050.broker.BuiltinBroker
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.mqtt.EmbeddedBroker
import org.ktcs.adapters.vda5050.sim.SimulatedVehicle
import org.ktcs.adapters.vda5050.sim.SimulatorOptions
import org.ktcs.adapters.vda5050.sim.simulatedVehicles
import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.bench.ProcStats
import java.net.InetAddress
import java.net.ServerSocket
import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit

/** What one step of the broker's message path cost per message received. */
data class StepFigures(val step: String, val messagesPerSecond: Double, val cpuMicros: Double, val switches: Double)

/**
 * What each step of a vehicle message's way through kTCS's embedded broker costs, in the bench's process: HiveMQ
 * alone (no extension: its floor), HiveMQ with a publish inbound interceptor that does nothing (HiveMQ hands every
 * message to its extension executor and back, the in-process link's hand-over without the link's work), and the
 * builtin broker (whose in-process listeners run on its own thread: no hand-over to measure). Per
 * message received: CPU microseconds of the broker's and extension executor's threads and their context switches.
 */
internal class BrokerSteps(private val model: PlantModel, private val simulator: SimulatorOptions) {
    fun run(rounds: Int): List<StepFigures> = (1..rounds).flatMap {
        listOf(
            measure("HiveMQ alone") { port -> hiveMq(port, null) },
            measure("HiveMQ + interceptor") { port -> hiveMq(port, doNothingExtension()) },
            measure("builtin broker") { port -> builtin(port) },
        )
    }

    /** A started broker, and how many PUBLISH packets it has received. */
    private class Started(val broker: AutoCloseable, val publishesReceived: () -> Long)

    private fun hiveMq(port: Int, extension: EmbeddedExtension?): Started {
        val broker = EmbeddedBroker("127.0.0.1", port, extension).also { it.start() }
        return Started(broker, broker::publishesReceived)
    }

    private fun builtin(port: Int): Started {
        val broker = BuiltinBroker(BrokerConfig(port = port)).also { it.start() }
        return Started(broker, broker::publishesReceived)
    }

    private fun measure(step: String, start: (Int) -> Started): StepFigures {
        val port = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }
        val executor = Executors.newScheduledThreadPool(2) { Thread(it, "vda5050-sim").apply { isDaemon = true } }
        val started = start(port)
        started.broker.use {
            val endpoint = BrokerEndpoint("127.0.0.1", port, tls = false)
            val vehicles = simulatedVehicles(model, simulator).map { SimulatedVehicle(it, endpoint, executor) }
            try {
                vehicles.forEach { it.start() }
                Thread.sleep(TimeUnit.SECONDS.toMillis(WARM_UP_SECONDS))
                val cpu = ThreadCpu(ProcStats.self())
                val switches = ThreadSwitches(ProcessHandle.current().pid())
                val received = started.publishesReceived()
                Thread.sleep(TimeUnit.SECONDS.toMillis(SECONDS))
                val messages = (started.publishesReceived() - received).coerceAtLeast(1).toDouble()
                val groups = setOf(ThreadCpu.BROKER_GROUP, ThreadCpu.IN_PROCESS_GROUP)
                val seconds = cpu.byGroup().filter { it.first in groups }.sumOf { it.second }
                val woken = switches.byGroup().filterKeys { it in groups }.values.sum()
                return StepFigures(step, messages / SECONDS, seconds * MICROS / messages, woken / messages)
            } finally {
                vehicles.forEach { runCatching { it.close() } }
                executor.shutdownNow()
            }
        }
    }

    private fun doNothingExtension(): EmbeddedExtension {
        val interceptor = PublishInboundInterceptor { _, _ -> }
        return EmbeddedExtension.builder().withId("do-nothing").withName("do nothing").withVersion("1")
            .withExtensionMain(
                object : ExtensionMain {
                    override fun extensionStart(input: ExtensionStartInput, output: ExtensionStartOutput) {
                        Services.initializerRegistry().setClientInitializer { _, client ->
                            client.addPublishInboundInterceptor(interceptor)
                        }
                    }

                    override fun extensionStop(input: ExtensionStopInput, output: ExtensionStopOutput) = Unit
                },
            ).build()
    }

    private companion object {
        const val WARM_UP_SECONDS = 8L
        const val SECONDS = 15L
        const val MICROS = 1e6
    }
}
