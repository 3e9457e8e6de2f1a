package org.ktcs.kernel.dispatching

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain

class DispatcherConfigurationTest : FunSpec({
    test("defaults are openTCS's, except that idle vehicles park and recharge and a vehicle takes the nearest order") {
        DispatcherConfiguration() shouldBe DispatcherConfiguration(
            orderPriorities = listOf(OrderPriority.BY_DEADLINE),
            vehiclePriorities = listOf(VehiclePriority.IDLE_FIRST, VehiclePriority.BY_ENERGY_LEVEL),
            vehicleCandidatePriorities = listOf(CandidatePriority.IDLE_FIRST, CandidatePriority.BY_ENERGY_LEVEL),
            orderCandidatePriorities = listOf(
                CandidatePriority.BY_DEADLINE,
                CandidatePriority.BY_INITIAL_ROUTING_COSTS,
            ),
            orderCandidateWindow = 50,
            deadlineAtRiskPeriodMillis = 60_000,
            assignRedundantOrders = false,
            parkIdleVehicles = true,
            parkIdleVehiclesDelayMillis = 0,
            considerParkingPositionPriorities = false,
            reparkVehiclesToHigherPriorityPositions = false,
            rechargeIdleVehicles = true,
            rechargeIdleVehiclesDelayMillis = 0,
            keepRechargingUntilFullyCharged = true,
        )
    }

    test("negative periods and delays are rejected with the offending value") {
        shouldThrow<IllegalArgumentException> { DispatcherConfiguration(deadlineAtRiskPeriodMillis = -1) }
            .message shouldContain "-1"
        shouldThrow<IllegalArgumentException> { DispatcherConfiguration(parkIdleVehiclesDelayMillis = -5) }
        shouldThrow<IllegalArgumentException> { DispatcherConfiguration(rechargeIdleVehiclesDelayMillis = -5) }
        shouldThrow<IllegalArgumentException> { DispatcherConfiguration(orderCandidateWindow = -1) }
            .message shouldContain "-1"
    }

    test("only the routing-cost keys need routes") {
        CandidatePriority.entries.filter { it.needsRoute } shouldBe
            listOf(CandidatePriority.BY_COMPLETE_ROUTING_COSTS, CandidatePriority.BY_INITIAL_ROUTING_COSTS)
    }
})
