package org.ktcs.examples.tcpdriver

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import kotlinx.serialization.json.int
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.api.event.DriverEvent
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.LoadedModel
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.services.StandardKernelServices
import kotlin.time.Duration.Companion.seconds

/**
 * The driver in a real kernel, with the test playing the vehicle over a real socket: commands arrive numbered and
 * never more than the queue holds, reports of position and energy reach the kernel, a client's message reaches the
 * vehicle, and the vehicle's properties reach the client and its events the kernel's event stream.
 */
class TcpVehicleDriverTest : FunSpec({
    val vehicle = PlayedVehicle()
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf(
            "web.bindAddress=127.0.0.1",
            "web.port=0",
            // Only the test's orders: no parking or recharging orders in between.
            "dispatcher.parkIdleVehicles=false",
            "dispatcher.rechargeIdleVehicles=false",
        ),
    )
    val application = KernelApplication(config, modelWithOneTcpVehicle(vehicle.port), listOf(TcpVehicleExtension()))
    val base = Regex("web API (http://\\S+)/v1").find(application.start())!!.groupValues[1]
    val kernel = KernelHttp(base)
    afterSpec {
        application.stop()
        vehicle.close()
    }

    fun tcpVehicle() = kernel.get("/vehicles/Tcp-01")

    test("the vehicle's position and energy reports reach the kernel") {
        vehicle.awaitDriver() shouldBe "CLEAR"
        vehicle.send("POSITION|Point-0027", "ENERGY|80", "STATE|IDLE")
        eventually(10.seconds) {
            tcpVehicle()["currentPosition"]!!.jsonPrimitive.content shouldBe "Point-0027"
            tcpVehicle()["energyLevel"]!!.jsonPrimitive.int shouldBe 80
        }
    }

    test("an order arrives as numbered commands, at most two at a time, and finishes when they are executed") {
        kernel.post(
            "/transportOrders/T1",
            """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}]}""",
        )
        val pending = ArrayDeque<List<String>>()
        var mostPending = 0
        var quietSpells = 0
        var loaded = false
        while (!loaded && quietSpells < 100) {
            // Commands keep coming while the vehicle has room; once the driver is quiet, execute the oldest.
            val line = vehicle.receiveWithin(300)
            if (line != null) {
                val command = LineProtocol.parse(line)
                command.name shouldBe "COMMAND"
                pending.addLast(command.fields)
                pending.size shouldBeLessThanOrEqual 2
                mostPending = maxOf(mostPending, pending.size)
            } else {
                quietSpells++
                val (id, point, operation) = pending.removeFirstOrNull() ?: continue
                vehicle.send("POSITION|$point", "EXECUTED|$id")
                loaded = operation == "Load cargo"
            }
        }
        vehicle.send("STATE|IDLE")
        eventually(10.seconds) {
            kernel.get("/transportOrders/T1")["state"]!!.jsonPrimitive.content shouldBe "FINISHED"
        }
        mostPending shouldBe 2
        tcpVehicle()["currentPosition"]!!.jsonPrimitive.content shouldBe "Point-0028"
    }

    test("a client's message reaches the vehicle") {
        kernel.post(
            "/vehicles/Tcp-01/commAdapter/message",
            """{"type":"beep","parameters":[{"key":"times","value":"2"}]}""",
        )
        vehicle.receive() shouldBe "MESSAGE|beep|times=2"
    }

    test("the vehicle's properties reach the client, and an empty value removes one") {
        vehicle.send("PROPERTY|firmware|1.4")
        eventually(10.seconds) {
            tcpVehicle()["properties"]!!.jsonObject["firmware"]!!.jsonPrimitive.content shouldBe "1.4"
        }
        vehicle.send("PROPERTY|firmware|")
        eventually(10.seconds) { tcpVehicle()["properties"]!!.jsonObject["firmware"].shouldBeNull() }
    }

    test("the vehicle's events reach the kernel's event stream") {
        val services = StandardKernelServices(application.kernel)
        val event = withTimeout(10.seconds) {
            coroutineScope {
                val first = async(start = CoroutineStart.UNDISPATCHED) {
                    services.events().filterIsInstance<DriverEvent>().first()
                }
                vehicle.send("EVENT|bumper|side=left|force=3")
                first.await()
            }
        }
        event.vehicle shouldBe "Tcp-01"
        event.type shouldBe "bumper"
        event.payload shouldBe mapOf("side" to "left", "force" to "3")
    }

    test("a withdrawn order clears the vehicle's command queue") {
        kernel.post(
            "/transportOrders/T2",
            """{"destinations":[{"locationName":"Goods out 01","operation":"Unload cargo"}]}""",
        )
        vehicle.receive() shouldStartWith "COMMAND|"
        kernel.post("/transportOrders/T2/withdrawal?immediate=true", "")
        generateSequence { vehicle.receive() }.first { !it.startsWith("COMMAND|") } shouldBe "CLEAR"
    }

    test("after a dropped connection the driver connects again and first clears what the vehicle still holds") {
        vehicle.dropConnection()
        eventually(10.seconds) { tcpVehicle()["state"]!!.jsonPrimitive.content shouldBe "UNKNOWN" }

        vehicle.awaitDriver() shouldBe "CLEAR"
        vehicle.send("POSITION|Point-0027", "STATE|IDLE")
        eventually(10.seconds) { tcpVehicle()["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
    }
})

private fun modelWithOneTcpVehicle(port: Int): LoadedModel {
    val demo = PlantModelLoader.loadDemo()
    val tcpVehicle = demo.model.vehicles.first().copy(
        name = "Tcp-01",
        properties = mapOf(
            "tcs:preferredAdapterClass" to TcpVehicleDriverFactory.NAME,
            TcpVehicleDriverFactory.PORT to port.toString(),
        ),
    )
    return demo.copy(model = demo.model.copy(vehicles = listOf(tcpVehicle)))
}
