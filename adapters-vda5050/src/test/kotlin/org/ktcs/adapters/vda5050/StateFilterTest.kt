package org.ktcs.adapters.vda5050

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.vda5050.protocol.AgvPosition
import org.ktcs.adapters.vda5050.protocol.BatteryState
import org.ktcs.adapters.vda5050.protocol.SafetyState
import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.adapters.vda5050.protocol.VehicleError

private fun state(headerId: Long, lastNode: String = "Point-0001", battery: Double = 80.2, x: Double = 1.0) = State(
    headerId, "2026-11-24T08:00:0${headerId % 10}Z", Vda.PROTOCOL_VERSION, "kTCS", "SIM-1", "o-1", 0, lastNode, 0,
    emptyList(), emptyList(), false, emptyList(), BatteryState(battery, false), "AUTOMATIC", emptyList(),
    SafetyState("NONE", false), agvPosition = AgvPosition(x, 0.0, 0.0, "map", true), distanceSinceLastNode = x,
)

/**
 * A vehicle repeats its state every second: a repetition that changes nothing the driver acts on costs no kernel task,
 * unless the driver waits for a confirmation, the connection changed, or the vehicle reports errors.
 */
class StateFilterTest : FunSpec({
    test("repetitions that differ in header, timestamp, pose, distance and battery fraction are filtered") {
        val filter = StateFilter()
        filter.worthATask(state(1)) shouldBe true // the first one always goes
        filter.worthATask(state(2)) shouldBe true // the driver waits for its first state until told otherwise
        filter.needEvery(false)
        filter.worthATask(state(3, battery = 80.7, x = 1.5)) shouldBe false
        filter.worthATask(state(4, lastNode = "Point-0002")) shouldBe true
        filter.worthATask(state(5, lastNode = "Point-0002", battery = 79.9)) shouldBe true // 80 % -> 79 %
        filter.worthATask(state(6, lastNode = "Point-0002", battery = 79.1)) shouldBe false
    }

    test("every message goes while the driver waits for a confirmation, after a reset, and with errors") {
        val filter = StateFilter()
        filter.worthATask(state(1)) shouldBe true
        filter.needEvery(true)
        filter.worthATask(state(2)) shouldBe true
        filter.needEvery(false)
        filter.worthATask(state(3)) shouldBe false
        filter.reset()
        filter.worthATask(state(4)) shouldBe true
        val failing = state(5).copy(errors = listOf(VehicleError("orderError", "WARNING")))
        filter.worthATask(failing) shouldBe true
        filter.worthATask(failing.copy(headerId = 6)) shouldBe true
    }
})
