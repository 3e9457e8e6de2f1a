package org.ktcs.kernel.core

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.context.RealTimeKernelContext
import org.ktcs.kernel.events.EventBus
import org.ktcs.kernel.orders.OrderSequencePool
import org.ktcs.kernel.orders.TransportOrderPool
import org.ktcs.kernel.simulation.SimulationKernel
import org.ktcs.kernel.workingset.PlantState
import java.time.Instant
import kotlin.concurrent.thread

/** Kernel state changed outside the kernel context fails at once in tests (JVM assertions on), where it changes. */
class KernelConfinementTest : FunSpec({
    val demo = PlantModelLoader.loadDemo().model

    fun offThread(change: () -> Unit): Throwable? {
        var failure: Throwable? = null
        thread { failure = runCatching(change).exceptionOrNull() }.join()
        return failure
    }

    test("the pools and the plant state refuse changes from outside the kernel context, also those without events") {
        val context = RealTimeKernelContext()
        try {
            val events = EventBus(context)
            val orders = TransportOrderPool(events, context)
            val sequences = OrderSequencePool(events, context)
            val plant = PlantState(demo, events)
            val order = TransportOrder("T", emptyList(), creationTime = Instant.EPOCH)

            shouldThrow<AssertionError> { orders.restore(order) }.message shouldContain "TransportOrderPool.restore"
            shouldThrow<AssertionError> { sequences.restore(OrderSequence("S", Instant.EPOCH)) }.message shouldContain
                "outside the kernel context"
            shouldThrow<AssertionError> {
                plant.setLocationLocked(demo.locations.first().name, true)
            }.message shouldContain
                "PlantState.setLocationLocked"
            orders.contains("T") shouldBe false

            context.call { orders.restore(order) }
            orders.contains("T") shouldBe true
        } finally {
            context.close()
        }
    }

    test("the vehicle controllers refuse changes from another thread than the kernel's") {
        val config = ConfigLoader().load(null, emptyMap(), emptyList())
        val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
        SimulationKernel(demo, config, listOf(drivers)).use { kernel ->
            val failure = offThread { kernel.core.requests.setPaused("Vehicle-01", true) }

            (failure is AssertionError) shouldBe true
            failure!!.message shouldContain "VehicleControllers.setPaused"
            kernel.core.plant.vehicle("Vehicle-01").paused shouldBe false
        }
    }
})
