package org.ktcs.kernel.orders

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.property.Exhaustive
import io.kotest.property.checkAll
import io.kotest.property.exhaustive.enum
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.order.TransportOrderState.ACTIVE
import org.ktcs.api.order.TransportOrderState.BEING_PROCESSED
import org.ktcs.api.order.TransportOrderState.DISPATCHABLE
import org.ktcs.api.order.TransportOrderState.FAILED
import org.ktcs.api.order.TransportOrderState.FINISHED
import org.ktcs.api.order.TransportOrderState.RAW
import org.ktcs.api.order.TransportOrderState.UNROUTABLE
import org.ktcs.api.order.TransportOrderState.WITHDRAWN
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.events.EventBus

class TransportOrderTransitionsTest : FunSpec({
    val edges = setOf(
        RAW to ACTIVE, RAW to UNROUTABLE, RAW to WITHDRAWN,
        ACTIVE to DISPATCHABLE, ACTIVE to UNROUTABLE, ACTIVE to WITHDRAWN,
        DISPATCHABLE to BEING_PROCESSED, DISPATCHABLE to WITHDRAWN,
        BEING_PROCESSED to FINISHED, BEING_PROCESSED to WITHDRAWN, BEING_PROCESSED to FAILED,
        WITHDRAWN to FAILED,
    )

    test("exactly the life cycle's edges are allowed, and nothing leaves a final state") {
        checkAll(Exhaustive.enum<TransportOrderState>(), Exhaustive.enum<TransportOrderState>()) { from, to ->
            TransportOrderTransitions.isAllowed(from, to) shouldBe ((from to to) in edges)
            if (from.isFinal) TransportOrderTransitions.successorsOf(from).shouldBeEmpty()
        }
    }

    context("the pool walks real life cycles and publishes each step") {
        withData(
            listOf(RAW, ACTIVE, DISPATCHABLE, BEING_PROCESSED, FINISHED),
            listOf(RAW, ACTIVE, DISPATCHABLE, BEING_PROCESSED, WITHDRAWN, FAILED),
            listOf(RAW, UNROUTABLE),
            listOf(RAW, ACTIVE, DISPATCHABLE, WITHDRAWN, FAILED),
        ) { path ->
            val clock = VirtualTimeKernelContext()
            val events = EventBus()
            val seen = mutableListOf<TransportOrderState>()
            events.listen { event ->
                (event as? org.ktcs.api.event.TransportOrderEvent)?.current?.let { seen += it.state }
            }
            val pool = TransportOrderPool(events, clock)
            pool.add(order())
            path.drop(1).forEach { pool.transition("T", it) }

            seen shouldBe path
            pool.require("T").finishedTime shouldBe clock.now()
        }
    }

    test("an illegal transition is refused with a message naming both states and the order") {
        val pool = TransportOrderPool(EventBus(), VirtualTimeKernelContext())
        pool.add(order())
        shouldThrow<IllegalStateChangeException> { pool.transition("T", FINISHED) }
            .message shouldBe "illegal transition RAW -> FINISHED for transport order 'T'"
        pool.require("T").state shouldBe RAW
    }
})

private fun order() = TransportOrder(
    "T",
    listOf(DriveOrder("0", Destination("A", "MOVE"))),
    creationTime = java.time.Instant.EPOCH,
)
