package org.ktcs.examples.clients

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeIn
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import kotlinx.coroutines.flow.filter
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.onEach
import kotlinx.coroutines.flow.takeWhile
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.adapters.loopback.LoopbackExtension
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import kotlin.time.Duration.Companion.seconds

/** The client examples against the real kernel application with the demo plant and its simulated vehicles. */
class KtcsClientTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("web.bindAddress=127.0.0.1", "web.port=0", "loopback.timeFactor=20"),
    )
    val application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(LoopbackExtension()))
    val base = Regex("web API (http://\\S+)/v1").find(application.start())!!.groupValues[1]
    val client = KtcsClient(base)
    afterSpec {
        client.close()
        application.stop()
    }

    suspend fun awaitFinal(name: String): TransportOrderView =
        eventually(60.seconds) { client.transportOrder(name).also { it.state shouldBeIn FINAL_STATES } }

    test("an order to a location finishes") {
        client.createOrderToLocation("To-Storage", "Storage 01", "Load cargo").name shouldBe "To-Storage"
        awaitFinal("To-Storage").state shouldBe "FINISHED"
    }

    test("an order to a point brings a vehicle there") {
        client.createOrderToPoint("To-Point", "Point-0020", vehicle = "Vehicle-03")
        awaitFinal("To-Point").state shouldBe "FINISHED"
        client.vehicle("Vehicle-03").currentPosition shouldBe "Point-0020"
    }

    test("the orders of a sequence are all carried out by one vehicle") {
        val orders = client.createOrderSequence(
            "Seq",
            listOf("Storage 01" to "Load cargo", "Goods out 01" to "Unload cargo"),
        )
        orders.map { it.wrappingSequence } shouldBe listOf("Seq", "Seq")
        val finished = orders.map { awaitFinal(it.name) }
        finished.map { it.state } shouldBe listOf("FINISHED", "FINISHED")
        finished.map { it.processingVehicle }.distinct() shouldHaveSize 1
    }

    test("an order withdrawn immediately fails") {
        client.createOrderToLocation("Withdrawn", "Goods out 01", "Unload cargo")
        client.withdrawOrder("Withdrawn", immediate = true)
        awaitFinal("Withdrawn").state shouldBe "FAILED"
    }

    test("withdrawing by vehicle ends the vehicle's order") {
        client.createOrderToPoint("By-Vehicle", "Point-0027", vehicle = "Vehicle-04")
        eventually(30.seconds) { client.transportOrder("By-Vehicle").state shouldBe "BEING_PROCESSED" }
        client.withdrawByVehicle("Vehicle-04", immediate = true)
        awaitFinal("By-Vehicle").state shouldBe "FAILED"
        client.vehicle("Vehicle-04").currentPosition shouldNotBe "Point-0027"
    }

    test("the WebSocket sends a snapshot, then the changes of an order up to FINISHED") {
        val states = withTimeout(60.seconds) {
            client.events("transportOrders")
                .onEach { message ->
                    withClue(message) { message["type"]!!.jsonPrimitive.content shouldNotBe "error" }
                    // The snapshot comes first: once it is here, no change of the new order can be missed.
                    if (message["type"]!!.jsonPrimitive.content == "snapshot") {
                        client.createOrderToLocation("Watched", "Storage 01", "Load cargo")
                    }
                }
                .filter { it.isEventOf("Watched") }
                .map { it["current"]!!.jsonObject["state"]!!.jsonPrimitive.content }
                .takeWhile { it != "FINISHED" }
                .toList()
        }
        states shouldContainAll listOf("DISPATCHABLE", "BEING_PROCESSED")
        client.transportOrder("Watched").state shouldBe "FINISHED"
    }
})

private fun JsonObject.isEventOf(order: String): Boolean =
    this["type"]?.jsonPrimitive?.content == "event" &&
        this["current"]?.jsonObject?.get("name")?.jsonPrimitive?.content == order

private val FINAL_STATES = setOf("FINISHED", "FAILED", "UNROUTABLE")
