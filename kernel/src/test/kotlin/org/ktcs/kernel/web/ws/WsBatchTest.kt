package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import java.time.Instant

class WsBatchTest : FunSpec({
    val holding = listOf(setOf("P1--P2", "P2"))
    val a0 = Vehicle("Vehicle-A", currentPosition = "P1", allocatedResources = holding)
    val atPoint = a0.copy(currentPosition = "P2")
    val posed = atPoint.copy(precisePosition = Position(2000, 0))
    val released = posed.copy(allocatedResources = listOf(setOf("P2")))
    val b0 = Vehicle("Vehicle-B", currentPosition = "P3")
    val b1 = b0.copy(currentPosition = "P4")
    val order = TransportOrder("order-1", driveOrders = emptyList(), creationTime = Instant.EPOCH)

    test("a vehicle's arrival (point, pose, released resources) goes out as one event") {
        val arrival = listOf(VehicleEvent(a0, atPoint), VehicleEvent(atPoint, posed), VehicleEvent(posed, released))

        WsBatch.coalesce(arrival) shouldContainExactly listOf(VehicleEvent(a0, released))
    }

    test("a change of its resources, state or order stays an event of its own") {
        val allocated = a0.copy(allocatedResources = holding + listOf(setOf("P2--P3", "P3")))
        val idle = a0.copy(state = VehicleState.IDLE)
        for (changed in listOf(allocated, idle, a0.copy(transportOrder = "order-1"))) {
            val events = listOf(VehicleEvent(a0, changed), VehicleEvent(changed, changed.copy(currentPosition = "P2")))

            WsBatch.coalesce(events) shouldContainExactly events
        }
    }

    test("another vehicle's change in between keeps both, in kernel order") {
        val events = listOf(VehicleEvent(a0, atPoint), VehicleEvent(b0, b1), VehicleEvent(atPoint, posed))

        WsBatch.coalesce(events) shouldContainExactly events
    }

    test("an order's change in between does not keep a vehicle's moves apart, and stays as it is") {
        val orderChanged = TransportOrderEvent(order, order.copy(currentRouteStepIndex = 1))
        val events = listOf(VehicleEvent(a0, atPoint), orderChanged, VehicleEvent(atPoint, posed))

        WsBatch.coalesce(events) shouldContainExactly listOf(VehicleEvent(a0, posed), orderChanged)
    }

    test("creations and removals are not merged") {
        val created = listOf(VehicleEvent(null, a0), VehicleEvent(a0, atPoint))
        val removed = listOf(VehicleEvent(a0, atPoint), VehicleEvent(atPoint, null))

        WsBatch.coalesce(created) shouldContainExactly created
        WsBatch.coalesce(removed) shouldContainExactly removed
    }
})
