package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.loopback.LoopbackFixtures.command
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder
import java.time.Instant

class LoopbackDriverOperationTest : FunSpec({
    val load = command("A--B", "A", "B", "Load cargo", "Station")
    val unload = command("A--B", "A", "B", "Unload cargo", "Station")

    fun order(vararg operations: String, current: Int = -1) = TransportOrder(
        name = "T",
        driveOrders = operations.mapIndexed { i, op -> DriveOrder("d$i", Destination("Station", op)) },
        creationTime = Instant.EPOCH,
        currentDriveOrderIndex = current,
    )

    fun Harness.devices() = context.reportsOf<Report.Devices>().map { it.devices }

    test("performs an operation for the operating time, EXECUTING, then reports the command executed") {
        val harness = Harness()
        harness.send(command("A--B", "A", "B", "Inspect", "Station"))
        harness.clock.advanceTo(12_000)
        harness.executedAt() shouldBe emptyList()
        harness.states().last() shouldBe VehicleState.EXECUTING
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(17_000L)
    }

    test("a command without a location has no operation") {
        val harness = Harness()
        harness.send(command("A--B", "A", "B", "Inspect", location = null))
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(12_000L)
    }

    test("the operating time can be set per vehicle") {
        val harness = Harness(vehicle = LoopbackFixtures.vehicle(LoopbackProperties.OPERATING_TIME to "2000"))
        harness.send(load)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(14_000L)
    }

    test("loading fills and unloading empties the load handling device before the command is reported") {
        val harness = Harness()
        harness.send(load)
        harness.clock.runUntilIdle()
        harness.devices().last() shouldBe listOf(LoadHandlingDevice("default", true))
        harness.context.reports.filterNot { it is Report.Event }.takeLast(3).first() shouldBe
            Report.Devices(listOf(LoadHandlingDevice("default", true)))
        harness.send(unload)
        harness.clock.runUntilIdle()
        harness.devices().last() shouldBe listOf(LoadHandlingDevice("default", false))
    }

    test("load and unload operations can be named per vehicle") {
        val harness = Harness(vehicle = LoopbackFixtures.vehicle(LoopbackProperties.LOAD_OPERATION to "Pick"))
        harness.send(command("A--B", "A", "B", "Pick", "Station"))
        harness.clock.runUntilIdle()
        harness.devices().last() shouldBe listOf(LoadHandlingDevice("default", true))
        harness.driver.canProcess(order("Pick")) shouldBe Explained.no("cannotLoadWhenLoaded")
    }

    test("vetoes orders that load a loaded or unload an empty vehicle, with openTCS's reasons") {
        val harness = Harness()
        harness.driver.canProcess(order("Unload cargo")) shouldBe Explained.no("cannotUnloadWhenNotLoaded")
        harness.driver.canProcess(order("Load cargo", "Load cargo")) shouldBe Explained.no("cannotLoadWhenLoaded")
        harness.driver.canProcess(order("Load cargo", "Unload cargo", "MOVE")) shouldBe Explained.YES
        harness.message(LoopbackMessages.SET_LOADED, "value" to "true")
        harness.driver.canProcess(order("Load cargo")) shouldBe Explained.no("cannotLoadWhenLoaded")
        harness.driver.canProcess(order("Unload cargo", "Load cargo")) shouldBe Explained.YES
        harness.driver.canProcess(order("Unload cargo", "Unload cargo")) shouldBe
            Explained.no("cannotUnloadWhenNotLoaded")
    }

    test("checks only the drive orders still ahead of an order being processed") {
        val harness = Harness()
        harness.message(LoopbackMessages.SET_LOADED, "value" to "true")
        harness.driver.canProcess(order("Load cargo", "Unload cargo", current = 1)) shouldBe Explained.YES
    }
})
