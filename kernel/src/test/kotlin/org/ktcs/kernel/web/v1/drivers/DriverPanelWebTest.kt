package org.ktcs.kernel.web.v1.drivers

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.DriverCommand
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.DriverPanel
import org.ktcs.api.driver.DriverParameter
import org.ktcs.api.driver.ParameterType
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriver
import org.ktcs.kernel.web.WebApiClient
import org.ktcs.kernel.web.WsTestClient
import java.net.URI
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.seconds

/** A step driver with a panel: it records the commands it gets and publishes each as an event. */
private class PanelDriver(name: String, context: DriverContext, val received: MutableList<DriverMessage>) :
    StepDriver(name, context) {
    override fun processMessage(message: DriverMessage) {
        received += message
        context.publishEvent("test:got", mapOf("command" to message.type) + message.parameters)
    }

    override fun panelState(): Map<String, String> = mapOf("received" to received.size.toString())
}

private class PanelDriverFactory : VehicleDriverFactory {
    val received = CopyOnWriteArrayList<DriverMessage>()
    override val name = "panel-step"
    override val description = "step vehicle with a panel"
    override val panel = DriverPanel(
        title = "Test panel",
        resourceDirectory = "org/ktcs/test/panel",
        classLoader = javaClass.classLoader,
        commands = listOf(
            DriverCommand(
                "setSpeed",
                "sets the speed",
                listOf(
                    DriverParameter("value", ParameterType.INTEGER, min = 0.0, max = 10.0),
                    DriverParameter("unit", ParameterType.CHOICE, required = false, values = listOf("Fast", "Slow")),
                ),
            ),
            DriverCommand("goTo", "teleports", listOf(DriverParameter("point", ParameterType.POINT))),
        ),
    )

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver =
        PanelDriver(vehicleName, context, received)
}

class DriverPanelWebTest : FunSpec({
    val factory = PanelDriverFactory()
    val extension = object : KtcsExtension {
        override val name = "panel-vehicles"

        override fun module(): Module = module { single { factory } bind VehicleDriverFactory::class }
    }
    val client = WebApiClient()
    val config = ConfigLoader().load(null, emptyMap(), listOf("web.bindAddress=127.0.0.1", "web.port=0"))
    val application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(extension))
    val base = Regex("web API (http://\\S+/v1)").find(application.start())!!.groupValues[1]
    afterSpec { application.stop() }

    // Every response is checked against kTCS's OpenAPI document.
    fun command(vehicle: String, body: String) = client.call("POST", "$base/vehicles/$vehicle/driverCommand", body)
    fun speed(value: String, extra: String = "") =
        """{"driver":"panel-step","command":"setSpeed","parameters":{"value":"$value"$extra}}"""

    test("the panel, the driver's state and the command queue of a vehicle") {
        val response = client.call("GET", "$base/vehicles/Vehicle-01/driverPanel")
        response.statusCode() shouldBe 200
        val panel = Json.parseToJsonElement(response.body()).jsonObject
        panel["driver"]!!.jsonPrimitive.content shouldBe "panel-step"
        panel["panel"]!!.jsonObject["commands"]!!.jsonArray.map {
            it.jsonObject["name"]!!.jsonPrimitive.content
        } shouldBe
            listOf("setSpeed", "goTo")
        panel["state"]!!.jsonObject.keys shouldBe setOf("received")
        client.call("GET", "$base/vehicles/Ghost/driverPanel").statusCode() shouldBe 404
    }

    test("a bad command is refused with a message naming the problem; the driver never sees it") {
        val before = factory.received.size
        command("Ghost", speed("3")).let {
            it.statusCode() shouldBe 404
            it.body() shouldContain "unknown vehicle 'Ghost'"
        }
        command("Vehicle-01", """{"driver":"loopback","command":"setSpeed"}""").let {
            it.statusCode() shouldBe 409
            it.body() shouldContain "vehicle 'Vehicle-01' is driven by 'panel-step', not by 'loopback'"
        }
        command("Vehicle-01", """{"driver":"panel-step","command":"fly"}""").body() shouldContain
            "driver 'panel-step' has no command 'fly'; it has: setSpeed, goTo"
        command("Vehicle-01", speed("11")).body() shouldContain
            "parameter 'value' must be a whole number from 0 to 10, was '11'"
        command("Vehicle-01", speed("2.5")).statusCode() shouldBe 400
        command("Vehicle-01", speed("3", ""","unit":"warp"""")).body() shouldContain
            "parameter 'unit' must be one of Fast, Slow, was 'warp'"
        command("Vehicle-01", speed("3", ""","colour":"red"""")).body() shouldContain
            "command 'setSpeed' has no parameter 'colour'"
        command("Vehicle-01", """{"driver":"panel-step","command":"setSpeed"}""").body() shouldContain
            "command 'setSpeed' needs parameter 'value'"
        command("Vehicle-01", """{"driver":"panel-step","command":"goTo","parameters":{"point":"Nowhere"}}""")
            .body() shouldContain "parameter 'point' must be the name of a point of the plant model, was 'Nowhere'"
        command("Vehicle-01", """{"command":"goTo"}""").body() shouldContain "driver is missing"
        factory.received.size shouldBe before
    }

    test("a good command reaches the driver as checked; its event reaches REST and WebSocket clients") {
        val socket = WsTestClient(client.http, base)
        socket.send("""{"type":"subscribe","topics":["driverEvents"]}""")
        socket.next()["type"]!!.jsonPrimitive.content shouldBe "snapshot"

        command("Vehicle-02", speed(" 7 ", ""","unit":"slow"""")).statusCode() shouldBe 200
        eventually(5.seconds) {
            factory.received.last() shouldBe DriverMessage("setSpeed", mapOf("value" to "7", "unit" to "Slow"))
        }
        val event = socket.next()
        event["topic"]!!.jsonPrimitive.content shouldBe "driverEvents"
        val current = event["current"]!!.jsonObject
        current["vehicle"]!!.jsonPrimitive.content shouldBe "Vehicle-02"
        current["type"]!!.jsonPrimitive.content shouldBe "test:got"
        current["payload"]!!.jsonObject["unit"]!!.jsonPrimitive.content shouldBe "Slow"

        val sse = client.http.send(
            HttpRequest.newBuilder(URI("$base/sse?/events/driverEvents=true")).build(),
            HttpResponse.BodyHandlers.ofLines(),
        )
        // Once the stream has answered, a change made is on it (the stream subscribed before answering).
        command("Vehicle-02", speed("4")).statusCode() shouldBe 200
        val frames = java.util.concurrent.CompletableFuture.supplyAsync {
            sse.body().iterator().asSequence().filter { it.startsWith("event: ") || it.startsWith("data: ") }
                .take(2).toList()
        }.get(10, java.util.concurrent.TimeUnit.SECONDS)
        frames[0] shouldBe "event: /events/driverEvents"
        frames[1] shouldContain
            """"vehicle":"Vehicle-02","type":"test:got","payload":{"command":"setSpeed","value":"4"}"""
        sse.body().close()

        val recent = Json.parseToJsonElement(client.call("GET", "$base/vehicles/Vehicle-02/driverEvents").body())
        recent.jsonArray.last().jsonObject["payload"]!!.jsonObject["command"]!!.jsonPrimitive.content shouldBe
            "setSpeed"
        socket.close()
    }
})
