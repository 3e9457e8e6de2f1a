package org.ktcs.kernel.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState

/** Issue #14: an order no vehicle can route must not wait as DISPATCHABLE for ever. */
class UnroutableOrderTest : FunSpec({
    test("an order whose resources to avoid cut off its destination is UNROUTABLE at once") {
        demoKernel().use { kernel ->
            val order = kernel.inKernel {
                createTransportOrder(
                    TransportOrderCreation(
                        "Cut-off",
                        listOf(Destination("Storage 01", "Load cargo")),
                        properties = mapOf("tcs:resourcesToAvoid" to "Point-0028"),
                    ),
                )
            }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)

            kernel.core.orders.require(order.name).state shouldBe TransportOrderState.UNROUTABLE
        }
    }

    test("an order for a vehicle that cannot drive to its destination is UNROUTABLE at once") {
        // Vehicle-01 is too long for every point: its routing graph has no edges at all.
        val tooLong = demoKernel("router.edgeEvaluators=BOUNDING_BOX") { model ->
            model.copy(
                vehicles = model.vehicles.map {
                    if (it.name == "Vehicle-01") it.copy(boundingBox = it.boundingBox.copy(length = 1_000_000)) else it
                },
            )
        }
        tooLong.use { kernel ->
            val order = kernel.inKernel {
                createTransportOrder(
                    TransportOrderCreation(
                        "Too-long",
                        listOf(Destination("Storage 01", "Load cargo"), Destination("Storage 02", "Unload cargo")),
                        intendedVehicle = "Vehicle-01",
                    ),
                )
            }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)

            kernel.core.orders.require(order.name).state shouldBe TransportOrderState.UNROUTABLE
        }
    }
})
