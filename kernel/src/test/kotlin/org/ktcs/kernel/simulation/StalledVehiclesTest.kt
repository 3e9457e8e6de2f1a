package org.ktcs.kernel.simulation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

class StalledVehiclesTest : FunSpec({
    test("lists the standing vehicles with an order, by name, with why they wait and for whom") {
        val vehicles = listOf(
            Vehicle("V3", state = VehicleState.IDLE, currentPosition = "A-03", transportOrder = "T3"),
            Vehicle("V1", state = VehicleState.IDLE, currentPosition = "A-01", transportOrder = "T1"),
            Vehicle("V2", state = VehicleState.EXECUTING, currentPosition = "A-02", transportOrder = "T2"),
            Vehicle("V4", state = VehicleState.IDLE, currentPosition = "Park-1"),
        )
        val waits = mapOf(
            "V1" to mapOf("V3" to setOf("A-03", "A-02 --- A-03")),
            "V3" to mapOf("V1" to setOf("A-01")),
        )
        val why = mapOf("V1" to "occupied", "V3" to "local_rule")

        stalledVehicleLines(vehicles, why::getValue, waits) shouldBe listOf(
            "stalled_vehicle: V1 at A-01 with T1: occupied, waits for V3 (A-02 --- A-03, A-03)",
            "stalled_vehicle: V3 at A-03 with T3: local_rule, waits for V1 (A-01)",
        )
    }

    test("a vehicle that waits for nobody says so by leaving the wait out") {
        val vehicles = listOf(Vehicle("V1", state = VehicleState.IDLE, transportOrder = "T1"))

        stalledVehicleLines(vehicles, { "park_test" }, emptyMap()) shouldBe
            listOf("stalled_vehicle: V1 at no position with T1: park_test")
    }
})
