package org.ktcs.kernel.reliability

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.maps.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrderCreation

/** Issue #14: raising a vehicle's integration level must never make two vehicles hold one point. */
class IntegrationLevelTest : FunSpec({
    test("a vehicle whose point another vehicle holds stays below RESPECTED, with a notification, until it is free") {
        demoKernel("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false").use { kernel ->
            val point = kernel.inKernel { plant.vehicle("Vehicle-01").currentPosition!! }
            kernel.inKernel { requests.setIntegrationLevel("Vehicle-01", IntegrationLevel.TO_BE_IGNORED) }
            kernel.inKernel {
                createTransportOrder(
                    TransportOrderCreation(
                        "Onto",
                        listOf(Destination(point, Operations.MOVE)),
                        intendedVehicle = "Vehicle-02",
                    ),
                )
            }
            kernel.context.runUntil { kernel.core.orders.require("Onto").state.isFinal }
            kernel.core.scheduler.allocations()["Vehicle-02"]!!.contains(point) shouldBe true

            val refused = shouldThrow<IllegalStateChangeException> {
                kernel.inKernel { requests.setIntegrationLevel("Vehicle-01", IntegrationLevel.TO_BE_UTILIZED) }
            }

            refused.message shouldContain "Vehicle-02"
            kernel.doublyHeld().shouldBeEmpty()
            kernel.core.plant.vehicle("Vehicle-01").integrationLevel shouldBe IntegrationLevel.TO_BE_IGNORED
            kernel.core.notifications.recent().last().text shouldContain "Vehicle-01"

            // Once the other vehicle has left, the level can be raised and the point is held by one vehicle.
            kernel.inKernel {
                createTransportOrder(
                    TransportOrderCreation(
                        "Away",
                        listOf(Destination("Storage 01", "Load cargo")),
                        intendedVehicle = "Vehicle-02",
                    ),
                )
            }
            kernel.context.runUntil { kernel.core.orders.require("Away").state.isFinal }
            kernel.inKernel { requests.setIntegrationLevel("Vehicle-01", IntegrationLevel.TO_BE_UTILIZED) }
            kernel.core.scheduler.allocations()["Vehicle-01"] shouldBe setOf(point)
            kernel.doublyHeld().shouldBeEmpty()
        }
    }
})
