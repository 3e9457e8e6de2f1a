package org.ktcs.kernel.simulation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import java.time.Instant

class VehicleTimeLedgerTest : FunSpec({
    test("one vehicle's time, from idle through an order, lands in one use at a time, scaled by the time factor") {
        var now = 0L
        val orders = HashMap<String, TransportOrder>()
        val ledger = VehicleTimeLedger({ now }, timeFactor = 2.0, orders::get) { it.startsWith("Sim-") }
        val drives = listOf(drive("L", "Load"), drive("U", "Unload"))
        val order =
            TransportOrder("Sim-1", drives, creationTime = Instant.EPOCH, state = TransportOrderState.DISPATCHABLE)
        var vehicle = Vehicle("V", state = VehicleState.IDLE, currentPosition = "P")
        fun order(changed: TransportOrder) {
            val before = orders.put(changed.name, changed)
            ledger.onEvent(TransportOrderEvent(before, changed))
        }
        fun vehicle(changed: Vehicle) {
            ledger.onEvent(VehicleEvent(vehicle, changed))
            vehicle = changed
        }
        ledger.start(listOf(vehicle))

        now = 10
        order(order)
        now = 15
        val assigned = order.copy(state = TransportOrderState.BEING_PROCESSED, processingVehicle = "V")
        order(assigned.copy(currentDriveOrderIndex = 0))
        vehicle(vehicle.copy(transportOrder = "Sim-1"))
        now = 20
        vehicle(vehicle.copy(state = VehicleState.EXECUTING))
        now = 30
        vehicle(vehicle.copy(currentPosition = "L"))
        now = 35
        order(orders.getValue("Sim-1").copy(currentDriveOrderIndex = 1))
        now = 50

        ledger.totals() shouldBe mapOf(
            VehicleTimeUse.DRIVING_LOADED to 30.0,
            VehicleTimeUse.DRIVING_EMPTY to 20.0,
            VehicleTimeUse.OPERATING to 10.0,
            VehicleTimeUse.HELD_BACK to 10.0,
            VehicleTimeUse.PARKING to 0.0,
            VehicleTimeUse.IDLE_ORDERS_WAITING to 10.0,
            VehicleTimeUse.IDLE_NOTHING_WAITING to 20.0,
        )
    }
})

private fun drive(point: String, operation: String) =
    DriveOrder("to $point", Destination(point, operation), route = Route(listOf(Step("to $point", "P", point)), 1))
