package org.ktcs.kernel.store

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.context.RealTimeKernelContext
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.simulation.SimulationKernel

/** A client's request that changes the kernel is answered only once its change is committed. */
class CommitBarrierTest : FunSpec({
    test("creating an order answers only after the store committed it, though the kernel has it at once") {
        val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
        val config = ConfigLoader().load(null, emptyMap(), emptyList())
        SimulationKernel(PlantModelLoader.loadDemo().model, config, listOf(drivers), RealTimeKernelContext()).use {
            val commit = CompletableDeferred<Unit>()
            var marked = 0L
            it.onKernel {
                it.core.commitThrough(object : CommitBarrier {
                    override fun mark(): Long = ++marked

                    override fun whenCommitted(mark: Long, committed: () -> Unit) {
                        commit.invokeOnCompletion { committed() }
                    }
                })
            }
            val creation = TransportOrderCreation("T1", listOf(Destination("Storage 01", "Load cargo")))

            runBlocking {
                val answer = async(Dispatchers.Default) { it.services.transportOrders.createTransportOrder(creation) }
                delay(300)

                answer.isCompleted shouldBe false
                it.onKernel { it.core.orders.get("T1") } shouldNotBe null
                commit.complete(Unit)
                answer.await().name shouldBe "T1"
            }
            marked shouldBe 1
        }
    }
})
