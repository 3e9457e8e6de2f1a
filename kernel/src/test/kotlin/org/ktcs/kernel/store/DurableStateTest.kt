package org.ktcs.kernel.store

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldNotContain
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Position
import org.ktcs.api.order.Destination
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.AllocationAudit
import java.nio.file.Files
import java.nio.file.Path
import java.sql.DriverManager

private fun order(name: String, incomplete: Boolean = false, sequence: String? = null) = TransportOrderCreation(
    name,
    listOf(Destination("Storage 01", "Load cargo"), Destination("Goods out 01", "Unload cargo")),
    incompleteName = incomplete,
    wrappingSequence = sequence,
    properties = mapOf("customer" to "K-42"),
)

class DurableStateTest : FunSpec({
    fun tempStore(): Path = tempdir("ktcs-store-test").toPath()

    test("orders and sequences are written, read back after a restart, equal to what they were") {
        val directory = tempStore()
        val before = RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            onKernel {
                createOrderSequence(OrderSequenceCreation("Seq-1", failureFatal = true))
                createTransportOrder(order("Order-1", sequence = "Seq-1"))
                createTransportOrder(order("Order-2"))
            }
            runUntil { orders.get("Order-1")?.state == TransportOrderState.FINISHED }
            val snapshot = onKernel { orders.all().toList() to sequences.all().toList() }
            crash()
            snapshot
        }

        RestartableKernel(RestartableKernel.settingsFor(directory)).use { kernel ->
            val after = kernel.onKernel { orders.all().toList() to sequences.all().toList() }
            after.first.first { it.name == "Order-1" } shouldBe before.first.first { it.name == "Order-1" }
            after.second shouldBe before.second
            after.first.map { it.name }.toSet() shouldBe before.first.map { it.name }.toSet()
        }
    }

    test("locks, vehicle settings and notifications are written and read back") {
        val directory = tempStore()
        RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            onKernel {
                setPathLocked("Point-0001 --- Point-0002", true)
                requests.setLocationLocked("Storage 02", true)
                requests.setPaused("Vehicle-02", true)
                requests.setIntegrationLevel("Vehicle-03", IntegrationLevel.TO_BE_RESPECTED)
                requests.updateVehicle("Vehicle-01") {
                    it.copy(
                        energyLevel = 37,
                        energyLevelThresholdSet = EnergyLevelThresholdSet(10, 80, 20, 95),
                        acceptableOrderTypes = setOf(AcceptableOrderType("Transport", 1)),
                        envelopeKey = "wide",
                        precisePosition = Position(1_000, 2_000),
                    )
                }
                publishNotification("test", NotificationLevel.IMPORTANT, "remember me")
            }
            crash()
        }

        RestartableKernel(RestartableKernel.settingsFor(directory)).use { kernel ->
            kernel.onKernel {
                plant.path("Point-0001 --- Point-0002").locked shouldBe true
                plant.location("Storage 02").locked shouldBe true
                plant.vehicle("Vehicle-02").paused shouldBe true
                plant.vehicle("Vehicle-03").integrationLevel shouldBe IntegrationLevel.TO_BE_RESPECTED
                val vehicle = plant.vehicle("Vehicle-01")
                vehicle.energyLevel shouldBe 37
                vehicle.energyLevelThresholdSet shouldBe EnergyLevelThresholdSet(10, 80, 20, 95)
                vehicle.acceptableOrderTypes shouldBe setOf(AcceptableOrderType("Transport", 1))
                vehicle.envelopeKey shouldBe "wide"
                vehicle.precisePosition shouldBe Position(1_000, 2_000)
                vehicle.integrationLevel shouldBe IntegrationLevel.TO_BE_UTILIZED
                notifications.recent().map { it.text } shouldContain "remember me"
            }
        }
    }

    test("the name generator never repeats a name after a restart, even on a clock that starts over") {
        val directory = tempStore()
        val first = RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            val name = onKernel { createTransportOrder(order("Gen-", incomplete = true)).name }
            crash()
            name
        }
        // Both runs start their virtual clock at the same instant: without the stored position the name repeats.
        val second = RestartableKernel(RestartableKernel.settingsFor(directory)).use { kernel ->
            kernel.onKernel { createTransportOrder(order("Gen-", incomplete = true)).name }
        }
        second shouldNotBe first
        (second > first) shouldBe true
    }

    test("an order under way is continued by default: its vehicle finishes it, nothing is allocated twice") {
        val directory = tempStore()
        val vehicle = RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            onKernel { createTransportOrder(order("Order-1")) }
            runUntil { plant.vehicles().any { it.transportOrder == "Order-1" && it.currentPosition != null } }
            val vehicle = onKernel { orders.require("Order-1").processingVehicle!! }
            crash()
            vehicle
        }

        RestartableKernel(RestartableKernel.settingsFor(directory)).use { kernel ->
            val audit = AllocationAudit()
            kernel.onKernel { events.listen(audit::onEvent) }
            kernel.recovered shouldContain "1 continued"
            kernel.runUntil { orders.require("Order-1").state.isFinal }
            val order = kernel.onKernel { orders.require("Order-1") }
            order.state shouldBe TransportOrderState.FINISHED
            order.processingVehicle shouldBe vehicle
            order.history.map { it.eventCode } shouldContain StateRecovery.KERNEL_RESTARTED
            audit.doubleAllocations shouldBe 0
            audit.sharedPositions shouldBe 0
        }
    }

    test("with persistence.recovery=WITHDRAW an order under way is withdrawn and its history says why") {
        val directory = tempStore()
        RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            onKernel {
                createTransportOrder(order("Order-1"))
                createTransportOrder(order("Order-2"))
                createTransportOrder(order("Order-3"))
                createTransportOrder(order("Order-4"))
                createTransportOrder(order("Order-5"))
            }
            runUntil { orders.get("Order-1")?.state == TransportOrderState.BEING_PROCESSED }
            crash()
        }

        RestartableKernel(RestartableKernel.settingsFor(directory, "persistence.recovery=WITHDRAW")).use { kernel ->
            val order = kernel.onKernel { orders.require("Order-1") }
            order.state shouldBe TransportOrderState.FAILED
            order.history.last { it.eventCode == StateRecovery.KERNEL_RESTARTED }.supplement shouldStartWith "withdrawn"
            // The orders that waited are dispatched again and finish.
            kernel.runUntil { orders.require("Order-5").state.isFinal }
            kernel.onKernel { orders.require("Order-5").state } shouldBe TransportOrderState.FINISHED
        }
    }

    test("the order-pool sweep deletes from the store too") {
        val directory = tempStore()
        RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            onKernel { createTransportOrder(order("Order-1")) }
            runUntil { orders.get("Order-1")?.state == TransportOrderState.FINISHED }
            crash()
        }
        storedNames(directory, "transport_orders") shouldContain "Order-1"

        val sweeping = RestartableKernel.settingsFor(directory, "orderpool.sweepAge=0", "orderpool.sweepInterval=1000")
        RestartableKernel(sweeping).run {
            runUntil { orders.get("Order-1") == null }
            crash()
        }
        storedNames(directory, "transport_orders") shouldNotContain "Order-1"
    }

    test("the store keeps the newest 1,000 notifications, not every one ever published") {
        val directory = tempStore()
        val published = StateJournal.NOTIFICATIONS_KEPT + 250
        RestartableKernel(RestartableKernel.settingsFor(directory)).run {
            repeat(published) { index ->
                onKernel { publishNotification("test", NotificationLevel.INFORMATIONAL, "note $index") }
                if (index % 100 == 99) committed()
            }
            crash()
        }
        val stored = storedNames(directory, "notifications").map { it.toLong() }

        stored.size shouldBeLessThanOrEqual StateJournal.NOTIFICATIONS_KEPT + StateJournal.NOTIFICATIONS_KEPT / 10
        stored.max() shouldBe stored.min() + stored.size - 1
        RestartableKernel(RestartableKernel.settingsFor(directory)).use { kernel ->
            kernel.onKernel { notifications.recent().map { it.text } } shouldContain "note ${published - 1}"
        }
    }

    test("a group that fails to be written leaves nothing of it in the store, and the next one is written alone") {
        val directory = tempStore()
        fun lock(name: String, value: Any) = StoreChange.Put(StoreTable.PLANT_LOCKS, name, value)
        StateStore.embedded(directory, synchronous = true).use { store ->
            // A value the codec cannot write fails the group after its first row was staged.
            shouldThrow<Exception> {
                store.write(listOf(lock("Path-1", StoredLock(StoredLock.PATH, true)), lock("Path-2", Any())), true)
            }
            store.write(listOf(lock("Path-3", StoredLock(StoredLock.PATH, true))), true)
            val names = mutableListOf<String>()
            store.rows(StoreTable.PLANT_LOCKS) { chunk -> chunk.forEach { names += it.first } }
            names shouldBe listOf("Path-3")
        }
    }

    test("a damaged store stops the start with what is wrong and how to recover, and stays as it was") {
        val directory = tempStore()
        val file = directory.resolve(StateStore.FILE_NAME)
        Files.write(file, ByteArray(8192) { (it * 31).toByte() })
        val bytes = Files.readAllBytes(file)
        val config = ConfigLoader().load(null, emptyMap(), RestartableKernel.settingsFor(directory))

        val error = shouldThrow<StoreException> { DurableState.open(config) }

        error.message!! shouldContain file.toString()
        error.message!! shouldContain "move it aside"
        error.message!! shouldContain "backup"
        Files.readAllBytes(file) shouldBe bytes
    }

    test("a second kTCS on the same store is refused while the first one runs") {
        val directory = tempStore()
        RestartableKernel(RestartableKernel.settingsFor(directory)).use {
            val config = ConfigLoader().load(null, emptyMap(), RestartableKernel.settingsFor(directory))
            shouldThrow<StoreException> { DurableState.open(config) }.message!! shouldContain "in use by another kTCS"
        }
    }

    test("a store whose rows cannot be read, or from a newer kTCS, is refused") {
        val directory = tempStore()
        RestartableKernel(RestartableKernel.settingsFor(directory)).crash()
        val url = "jdbc:sqlite:${directory.resolve(StateStore.FILE_NAME)}"
        DriverManager.getConnection(url).use {
            it.createStatement().executeUpdate("INSERT INTO transport_orders VALUES ('Broken', '{not json')")
        }
        val config = ConfigLoader().load(null, emptyMap(), RestartableKernel.settingsFor(directory))
        shouldThrow<StoreException> { DurableState.open(config) }.message!! shouldContain "row 'Broken'"

        DriverManager.getConnection(url).use {
            it.createStatement().executeUpdate("DELETE FROM transport_orders")
            it.createStatement().executeUpdate(
                "INSERT INTO flyway_schema_history (installed_rank, version, description, type, script, " +
                    "installed_by, execution_time, success) VALUES (99, '99', 'future', 'SQL', 'V99', 'x', 0, 1)",
            )
        }
        shouldThrow<StoreException> { DurableState.open(config) }.message!! shouldContain "newer kTCS"
    }
})

private fun storedNames(directory: Path, table: String): List<String> =
    DriverManager.getConnection("jdbc:sqlite:${directory.resolve(StateStore.FILE_NAME)}").use { connection ->
        connection.createStatement().executeQuery("SELECT name FROM $table").use {
            buildList { while (it.next()) add(it.getString(1)) }
        }
    }
