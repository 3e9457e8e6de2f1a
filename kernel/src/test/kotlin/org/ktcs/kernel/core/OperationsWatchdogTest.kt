package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel
import java.time.Instant

/** openTCS's watchdog checks as notifications: stranded vehicles, waiting and late orders, positions off route. */
class OperationsWatchdogTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf(
            "dispatcher.parkIdleVehicles=false",
            "dispatcher.rechargeIdleVehicles=false",
            "watchdog.strandedVehicleCheckInterval=1000",
            "watchdog.strandedVehicleDurationThreshold=5000",
            "watchdog.transportOrderCheckInterval=1000",
            "watchdog.idleTransportOrderDurationThreshold=5000",
        ),
    )
    val drivers = RecordingStepDrivers()
    val demo = PlantModelLoader.loadDemo().model
    val trip = listOf(Destination("Goods in north 01", "Load cargo"), Destination("Goods out 02", "Unload cargo"))

    fun SimulationKernel.notifications(about: String) =
        core.notifications.recent().map { it.text }.filter { about in it }

    fun SimulationKernel.runFor(millis: Long) = context.runUntilTime(context.elapsedMillis() + millis)

    test("a vehicle idle off a park position is reported stranded once, after the threshold") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.execute(settleMillis = 50) { drivers.contexts.getValue("Vehicle-01").reportPosition("Point-0001") }
            kernel.runFor(3_000)
            kernel.notifications("is stranded").shouldBeEmpty()
            kernel.runFor(10_000)
            kernel.notifications("is stranded").single() shouldStartWith
                "vehicle Vehicle-01 is stranded: idle at Point-0001, which is no park position, without an order"
        }
    }

    test("an order waiting longer than the threshold is reported once, with its reason") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.execute { requests.setPaused("Vehicle-02", true) }
            kernel.execute { createTransportOrder(TransportOrderCreation("T", trip, intendedVehicle = "Vehicle-02")) }
            kernel.runFor(3_000)
            kernel.notifications("has waited").shouldBeEmpty()
            kernel.runFor(10_000)
            kernel.notifications("has waited").single() shouldContain ": intended vehicle Vehicle-02: paused"
        }
    }

    test("an unfinished order past its deadline is reported once") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.execute { requests.setPaused("Vehicle-02", true) }
            val deadline = kernel.context.now().plusMillis(2_000)
            kernel.execute {
                createTransportOrder(
                    TransportOrderCreation("Late", trip, intendedVehicle = "Vehicle-02", deadline = deadline),
                )
            }
            kernel.runFor(1_000)
            kernel.notifications("past its deadline").shouldBeEmpty()
            kernel.runFor(5_000)
            kernel.notifications("past its deadline") shouldHaveSize 1
        }
    }

    test("a vehicle that reports a point off its route is reported") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.execute(settleMillis = 500) {
                createTransportOrder(TransportOrderCreation("T", trip, intendedVehicle = "Vehicle-01"))
            }
            kernel.execute(settleMillis = 10) { drivers.contexts.getValue("Vehicle-01").reportPosition("Point-0040") }
            kernel.notifications("not on its route").single() shouldStartWith
                "vehicle Vehicle-01 reports position Point-0040, which is not on its route"
        }
    }
})
