package org.ktcs.kernel.store

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.order.VehicleOrientation
import java.lang.reflect.Modifier
import java.time.Instant

/** A stored order reads back as the order that was stored, every field of it, with and without its optional parts. */
class StateCodecTest : FunSpec({
    val route = Route(
        listOf(
            Step(null, null, "Point-0001", VehicleOrientation.UNDEFINED, 0, true),
            Step("Point-0001 --- Point-0002", "Point-0001", "Point-0002", VehicleOrientation.BACKWARD, 1, false),
        ),
        costs = 4_200_000_000L,
    )
    val full = TransportOrder(
        name = "Order-7",
        driveOrders = listOf(
            DriveOrder(
                "Order-7-0",
                Destination("Storage 01", "Load cargo", mapOf("tray" to "2", "side" to "left")),
                route,
                DriveOrderState.FINISHED,
            ),
            DriveOrder("Order-7-1", Destination("Point-0002", "MOVE"), null, DriveOrderState.TRAVELLING),
        ),
        type = "Transport",
        state = TransportOrderState.BEING_PROCESSED,
        creationTime = Instant.ofEpochSecond(1_700_000_000, 123_456_789),
        deadline = Instant.ofEpochSecond(1_700_003_600, 1),
        finishedTime = Instant.ofEpochSecond(1_700_000_100, 5),
        intendedVehicle = "Vehicle-01",
        processingVehicle = "Vehicle-02",
        dependencies = setOf("Order-5", "Order-6"),
        wrappingSequence = "Sequence-1",
        dispensable = true,
        peripheralReservationToken = "token",
        currentDriveOrderIndex = 1,
        currentRouteStepIndex = 0,
        properties = mapOf("priority" to "high", "quoted \"\\ value" to "ü\n"),
        history = listOf(
            HistoryEntry(Instant.ofEpochSecond(1_700_000_000, 123_456_789), "tcsHistoryEntry.order.created"),
            HistoryEntry(Instant.ofEpochSecond(1_700_000_050), "tcsHistoryEntry.order.assigned", "Vehicle-02"),
        ),
    )

    fun fields(order: TransportOrder) = TransportOrder::class.java.declaredFields
        .filter { !Modifier.isStatic(it.modifiers) }
        .associate { field -> field.name to field.also { it.isAccessible = true }.get(order) }

    test("the full order sets every field of a transport order to something other than its default") {
        // A field added to TransportOrder but not set here would go unchecked by the round trip below.
        val defaults = fields(TransportOrder(name = "", driveOrders = emptyList(), creationTime = Instant.EPOCH))
        fields(full).filter { (name, value) -> defaults[name] == value }.keys.shouldBeEmpty()
    }

    test("an order with routes, history, properties and dependencies reads back equal to what was written") {
        StateCodec.order(StateCodec.write(full)) shouldBe full
    }

    test("an order is written by hand as Jackson writes it, every field, with and without its optional parts") {
        // A field added to TransportOrder (set in the full order, see above) but not to the writer fails here.
        val minimal = TransportOrder(name = "Order-8", driveOrders = emptyList(), creationTime = Instant.EPOCH)
        listOf(full, minimal).forEach { order -> StateCodec.write(order) shouldBe StateCodec.jackson(order) }
    }

    test("the orders of a store read back equal, their equal routes as one instance") {
        val read = StateCodec.orders()
        val first = read(StateCodec.write(full))
        val second = read(StateCodec.write(full.copy(name = "Order-11")))
        first shouldBe full
        second shouldBe full.copy(name = "Order-11")
        (second.driveOrders[0].route === first.driveOrders[0].route) shouldBe true
    }

    test("an order with every optional field at its default reads back equal") {
        val bare = TransportOrder(
            name = "Order-8",
            driveOrders = listOf(DriveOrder("Order-8-0", Destination("Point-0003", "PARK"))),
            creationTime = Instant.ofEpochSecond(1),
        )
        StateCodec.order(StateCodec.write(bare)) shouldBe bare
    }

    test("fields missing from the stored JSON take the defaults, unknown ones are skipped") {
        val json = """{"name":"Order-9","creationTime":"5:0","future":{"a":[1,2]},"driveOrders":
            [{"name":"D","destination":{"target":"Point-0001","operation":"MOVE"}}]}"""
        StateCodec.order(json) shouldBe TransportOrder(
            name = "Order-9",
            driveOrders = listOf(DriveOrder("D", Destination("Point-0001", "MOVE"))),
            creationTime = Instant.ofEpochSecond(5),
        )
    }

    test("a stored order without a required field is refused with a message that names it") {
        shouldThrow<Exception> { StateCodec.order("""{"name":"Order-10","driveOrders":[]}""") }
            .message shouldContain "creationTime"
    }
})
