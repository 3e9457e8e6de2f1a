package org.ktcs.adapters.vda5050

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import org.ktcs.adapters.vda5050.mqtt.MessageLink
import org.ktcs.adapters.vda5050.protocol.AgvPosition
import org.ktcs.adapters.vda5050.protocol.Vda5050Json
import org.ktcs.adapters.vda5050.protocol.Visualization
import java.nio.ByteBuffer

/** A link that hands the test the handlers the driver registers. */
private class RecordingLink : MessageLink {
    val handlers = mutableMapOf<String, (ByteBuffer) -> Unit>()

    override fun listen(topic: String, qos: Int, handler: (ByteBuffer) -> Unit) {
        handlers[topic] = handler
    }

    override fun stopListening(topic: String) {
        handlers.remove(topic)
    }

    override fun send(topic: String, payload: ByteArray, qos: Int) = Unit
}

/**
 * The visualization throttle (openTCS's `minVisualizationInterval`, 500 ms by default) drops a message before its
 * payload is read: at 10 Hz, four of five visualization messages cost neither a schema check nor a parse.
 */
class VehicleTopicsTest : FunSpec({
    test("visualization messages within minVisualizationInterval are dropped without being read") {
        val link = RecordingLink()
        var now = 1_000L
        val properties = Vda5050Properties.read("Vehicle-01", vdaProperties("SIM-1"))
        val topics = VehicleTopics("Vehicle-01", properties, { link }, millis = { now })
        val received = mutableListOf<Any>()
        topics.listen { received += it }
        val visualization = link.handlers.getValue("uagv/v2/kTCS/SIM-1/visualization")
        fun message(x: Double) = ByteBuffer.wrap(
            Vda5050Json.encodeToString(
                Visualization.serializer(),
                Visualization(
                    1,
                    "2026-11-24T08:00:00Z",
                    "2.0.0",
                    "kTCS",
                    "SIM-1",
                    AgvPosition(x, 0.0, 0.0, "map", true),
                ),
            ).toByteArray(),
        ).asReadOnlyBuffer()

        val payloads = (0 until 10).map { i ->
            message(i.toDouble()).also {
                now += 100
                visualization(it)
            }
        }
        received shouldHaveSize 2 // at 1100 ms and at 1600 ms
        topics.decoded.get() shouldBe 2
        payloads.count { it.position() > 0 } shouldBe 2 // the eight others were never touched
        received.first().shouldBeInstanceOf<Visualization>().agvPosition!!.x shouldBe 0.0
        received.last().shouldBeInstanceOf<Visualization>().agvPosition!!.x shouldBe 5.0
    }

    test("a visualization message is decoded when valid and dropped when not, plain or with escapes") {
        val link = RecordingLink()
        var now = 1_000L
        val properties = Vda5050Properties.read("Vehicle-01", vdaProperties("SIM-1"))
        val topics = VehicleTopics("Vehicle-01", properties, { link }, millis = { now })
        val received = mutableListOf<Visualization>()
        topics.listen { received += it as Visualization }
        val visualization = link.handlers.getValue("uagv/v2/kTCS/SIM-1/visualization")
        fun send(position: String) {
            now += 1_000
            val json = """{"headerId":1,"timestamp":"2026-11-24T08:00:00Z","version":"2.0.0","manufacturer":"kTCS",""" +
                """"serialNumber":"SIM-1","agvPosition":$position}"""
            visualization(ByteBuffer.wrap(json.toByteArray()))
        }

        send("""{"x":1.5,"y":2,"theta":0.5,"mapId":"map","positionInitialized":true}""")
        send("""{"x":2.5,"y":2,"theta":0.5,"mapId":"m\u0061p","positionInitialized":true}""")
        send("""{"x":3.5,"y":2,"theta":0.5,"mapId":"map","positionInitialized":true,"localizationScore":1.5}""")
        send("""{"x":4.5,"y":2,"theta":0.5,"mapId":"map","positionInitialized":"yes"}""")
        send("""{"x":5.5,"y":2,"theta":0.5,"positionInitialized":true}""") // no mapId

        received.map { it.agvPosition!!.x to it.agvPosition!!.mapId } shouldBe listOf(1.5 to "map", 2.5 to "map")
    }
})
