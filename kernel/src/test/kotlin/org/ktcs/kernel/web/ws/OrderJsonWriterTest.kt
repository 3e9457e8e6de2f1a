package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.constant
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.orNull
import io.kotest.property.arbitrary.set
import io.kotest.property.arbitrary.shuffle
import io.kotest.property.arbitrary.subsequence
import io.kotest.property.checkAll
import kotlinx.serialization.descriptors.elementNames
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonObject
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.order.VehicleOrientation
import org.ktcs.kernel.orders.HistoryCodes
import org.ktcs.kernel.orders.waitingReason
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.SseTransportOrderDto
import org.ktcs.kernel.web.v1.events.toSseDto
import org.ktcs.kernel.web.ws.JsonArbs.shared
import org.ktcs.kernel.web.ws.JsonArbs.text
import java.time.Instant

/**
 * The order writer against the encoding it replaces: kotlinx's of the DTO, and fields cut from that by
 * [rewriteFields]. Compared as bytes (shown as Latin-1, one character per byte, so a failure shows every byte).
 * [EncodedOrders] keeps its values for all orders, whose names and seldom changing objects repeat: kept values must be
 * reused only for the objects they were made of.
 */
class OrderJsonWriterTest : FunSpec({
    fun kotlinx(order: TransportOrder) =
        utf8(V1Json.json.encodeToString(SseTransportOrderDto.serializer(), order.toSseDto()))

    fun bytes(json: ByteArray) = String(json, Charsets.ISO_8859_1)

    val fieldNames = SseTransportOrderDto.serializer().descriptor.elementNames.toList()

    test("an order is written byte for byte as kotlinx encodes its DTO") {
        val seen = mutableSetOf<String>()

        checkAll(3000, OrderArbs.order) { order ->
            bytes(EncodedOrders.marked(order).full) shouldBe bytes(kotlinx(order))
            seen += OrderArbs.casesOf(order)
        }

        seen shouldContainAll OrderArbs.CASES
    }

    test("an order without some of its fields is what the byte scan cut from kotlinx's encoding") {
        val omitted = arbitrary { Arb.shuffle(Arb.subsequence(fieldNames + "noSuchField").bind()).bind() }

        checkAll(3000, OrderArbs.order, omitted) { order, fields ->
            val marked = EncodedOrders.marked(order)
            bytes(marked.without(fields)) shouldBe bytes(rewriteFields(kotlinx(order), fields))
            bytes(marked.full) shouldBe bytes(kotlinx(order))
        }
    }

    test("an order without its drive orders and history reads neither") {
        val untouchable = object : AbstractList<Nothing>() {
            override val size: Int get() = error("read")

            override fun get(index: Int) = error("read")
        }
        val order = TransportOrder(
            name = "T\"1",
            driveOrders = untouchable,
            state = TransportOrderState.BEING_PROCESSED,
            creationTime = Instant.EPOCH,
            history = untouchable,
        )
        val expected = order.copy(driveOrders = emptyList(), history = emptyList())

        val json = EncodedOrders.marked(order).without(listOf("driveOrders", "history")).decodeToString()

        Json.parseToJsonElement(json) shouldBe Json.parseToJsonElement(
            rewriteFields(kotlinx(expected), listOf("driveOrders", "history")).decodeToString(),
        )
        Json.parseToJsonElement(json).jsonObject.keys.size shouldBe fieldNames.size - 3
    }
})

/** Orders with anything their JSON can hold, their seldom changing objects often shared as copies share them. */
private object OrderArbs {
    private val properties = Arb.map(text, text, 0, 4)

    private val step = arbitrary {
        Step(
            path = text.orNull(NULLS).bind(),
            sourcePoint = text.orNull(NULLS).bind(),
            destinationPoint = text.bind(),
            vehicleOrientation = Arb.enum<VehicleOrientation>().bind(),
            routeIndex = Arb.int().bind(),
            executionAllowed = Arb.boolean().bind(),
        )
    }
    private val route = arbitrary { Route(Arb.list(step, 0..5).bind(), Arb.long().bind()) }

    private val destination = arbitrary { Destination(text.bind(), text.bind(), shared(properties).bind()) }

    private val driveOrder = arbitrary {
        DriveOrder(
            name = shared(text).bind(),
            destination = shared(destination).bind(),
            route = shared(route).orNull(NULLS).bind(),
            state = Arb.enum<DriveOrderState>().bind(),
        )
    }

    // The codes `waitingReason` looks for among any others.
    private val eventCode = Arb.choice(
        Arb.element(HistoryCodes.ORDER_DISPATCHING_DEFERRED, HistoryCodes.ORDER_DISPATCHING_RESUMED),
        text,
    )
    private val historyEntry = arbitrary {
        HistoryEntry(JsonArbs.instant.bind(), eventCode.bind(), Arb.choice(Arb.constant(""), text).bind())
    }
    private val history = Arb.choice(Arb.list(historyEntry, 0..4), Arb.list(historyEntry, 20..40))

    // The states in which an order may be waiting for something come up more often.
    private val state = Arb.choice(
        Arb.enum<TransportOrderState>(),
        Arb.element(TransportOrderState.DISPATCHABLE, TransportOrderState.ACTIVE),
    )

    val order = arbitrary {
        TransportOrder(
            name = shared(text).bind(),
            driveOrders = shared(Arb.list(driveOrder, 0..3)).bind(),
            type = shared(text).bind(),
            state = state.bind(),
            creationTime = shared(JsonArbs.instant).bind(),
            deadline = shared(Arb.choice(Arb.constant(Instant.MAX), JsonArbs.instant)).bind(),
            finishedTime = shared(JsonArbs.instant).orNull(NULLS).bind(),
            intendedVehicle = text.orNull(NULLS).bind(),
            processingVehicle = text.orNull(NULLS).bind(),
            dependencies = shared(Arb.set(text, 0..3)).bind(),
            wrappingSequence = text.orNull(NULLS).bind(),
            dispensable = Arb.boolean().bind(),
            peripheralReservationToken = text.orNull(NULLS).bind(),
            currentDriveOrderIndex = Arb.int().bind(),
            currentRouteStepIndex = Arb.int().bind(),
            properties = shared(properties).bind(),
            history = shared(history).bind(),
        )
    }

    /** The cases that the generated orders must have covered. */
    val CASES = setOf("waiting", "not waiting", "no route", "route", "unfinished", "far deadline", "no history")

    fun casesOf(order: TransportOrder): Set<String> = setOfNotNull(
        if (order.waitingReason() != null) "waiting" else "not waiting",
        "no route".takeIf { order.driveOrders.any { it.route == null } },
        "route".takeIf { order.driveOrders.any { it.route != null } },
        "unfinished".takeIf { order.finishedTime == null },
        "far deadline".takeIf { order.deadline == Instant.MAX },
        "no history".takeIf { order.history.isEmpty() },
    )

    private const val NULLS = 0.3
}
