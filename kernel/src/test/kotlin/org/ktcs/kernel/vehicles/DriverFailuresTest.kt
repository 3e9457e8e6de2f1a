package org.ktcs.kernel.vehicles

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriver
import org.ktcs.kernel.simulation.SimulationKernel

/** A driver that refuses bad settings and bad messages with IllegalArgumentException, as drivers naturally do. */
private class PickyDriverFactory : VehicleDriverFactory {
    override val name = "picky"
    override val description = "refuses a vehicle without a numeric picky:port"

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver {
        requireNotNull(context.vehicle().properties["picky:port"]?.toIntOrNull()) {
            "vehicle $vehicleName: picky:port must be a number"
        }
        return object : StepDriver(vehicleName, context) {
            override fun processMessage(message: DriverMessage) {
                require('|' !in message.type) { "a message type must not contain '|'" }
            }
        }
    }
}

class DriverFailuresTest : FunSpec({
    val plant = PlantModel(
        "two points",
        points = listOf(Point("A"), Point("B")),
        paths = listOf(Path("A --- B", "A", "B", length = 1000)),
        vehicles = listOf(
            Vehicle("Good", properties = mapOf("picky:port" to "1", "loopback:initialPosition" to "A")),
            Vehicle("Bad", properties = mapOf("picky:port" to "x", "loopback:initialPosition" to "B")),
        ),
    )

    fun kernel() = SimulationKernel(
        plant,
        ConfigLoader().load(null, emptyMap(), emptyList()),
        listOf(module { single { PickyDriverFactory() } bind VehicleDriverFactory::class }),
    )

    test("a vehicle whose driver refuses its settings starts without a driver; the others and the kernel start") {
        kernel().use { kernel ->
            val controllers = kernel.core.controllers
            controllers.driverName("Good") shouldBe "picky"
            controllers.driverName("Bad") shouldBe null
            kernel.core.notifications.recent().single { it.source == "Bad" }.text shouldContain
                "picky:port must be a number"
        }
    }

    test("a message the driver refuses is bad input (400), not an internal error") {
        kernel().use { kernel ->
            var outcome: Result<Unit>? = null
            kernel.context.execute {
                outcome = runCatching { kernel.core.requests.sendDriverMessage("Good", DriverMessage("a|b")) }
            }
            kernel.context.runUntil { outcome != null }

            val error = shouldThrow<InvalidRequestException> { outcome!!.getOrThrow() }
            error.message shouldContain "the driver of vehicle 'Good' refused the message"
        }
    }
})
