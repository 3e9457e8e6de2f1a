package org.ktcs.kernel.store

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import org.ktcs.api.order.Destination
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState

/** The same store on a real PostgreSQL server (its own cluster, started for this spec on port 18165). */
class PostgresStoreTest : FunSpec({
    val cluster = PostgresCluster.start(PORT)
    afterSpec { cluster?.close() }

    fun settings(vararg more: String) = cluster!!.let {
        listOf("persistence.url=${it.url}", "persistence.username=${it.user}", "kernel.dataDirectory=unused") + more
    }

    test("orders, sequences, locks and the name generator survive a restart on PostgreSQL").config(
        enabled = cluster != null,
    ) {
        val destinations = listOf(Destination("Storage 01", "Load cargo"), Destination("Goods out 01", "Unload cargo"))
        val (before, firstName) = RestartableKernel(settings()).run {
            val name = onKernel {
                createOrderSequence(OrderSequenceCreation("Seq-1"))
                createTransportOrder(TransportOrderCreation("Order-1", destinations, wrappingSequence = "Seq-1"))
                setPathLocked("Point-0001 --- Point-0002", true)
                createTransportOrder(TransportOrderCreation("Gen-", destinations, incompleteName = true)).name
            }
            runUntil { orders.get("Order-1")?.state == TransportOrderState.BEING_PROCESSED }
            val snapshot = onKernel { orders.require("Order-1") to sequences.require("Seq-1") }
            crash()
            snapshot to name
        }

        RestartableKernel(settings()).use { kernel ->
            val (order, sequence) = kernel.onKernel { orders.require("Order-1") to sequences.require("Seq-1") }
            order.name shouldBe before.first.name
            order.properties shouldBe before.first.properties
            order.history.take(before.first.history.size) shouldBe before.first.history
            sequence shouldBe before.second
            kernel.onKernel { plant.path("Point-0001 --- Point-0002").locked } shouldBe true
            kernel.onKernel {
                createTransportOrder(TransportOrderCreation("Gen-", destinations, incompleteName = true)).name
            } shouldNotBe firstName
            kernel.runUntil { orders.require("Order-1").state.isFinal }
            kernel.onKernel { orders.require("Order-1").state } shouldBe TransportOrderState.FINISHED
        }
    }
}) {
    private companion object {
        const val PORT = 18165
    }
}
