package org.ktcs.adapters.vda5050.protocol

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.JsonPrimitive

private fun node(id: Int, sequence: Int, released: Boolean) = Node(
    "Point-$id",
    sequence,
    released,
    if (released && id == 4) {
        listOf(
            Action("pick", "a-$id", "HARD", listOf(ActionParameter("lhd", JsonPrimitive("LHD1")))),
        )
    } else {
        emptyList()
    },
    NodePosition(id * 1.25, -id / 3.0, "map", theta = if (id % 2 == 0) Math.PI / 2 else null, allowedDeviationXY = 0.5),
)

private fun edge(id: Int, sequence: Int, released: Boolean) =
    Edge(
        "Point-$id --- Point-${id + 1}",
        sequence,
        released,
        "Point-$id",
        "Point-${id + 1}",
        maxSpeed = 1.5,
        length = 1.25,
    )

/** An update: base nodes [from]..[baseTo] (released), horizon up to [to]; sequence ids as the driver gives them. */
private fun order(orderId: String, updateId: Long, from: Int, baseTo: Int, to: Int, zoneSetId: String? = null) = Order(
    updateId, "2026-11-24T08:00:0${updateId}Z", Vda.PROTOCOL_VERSION, "kTCS", "SIM-1", orderId, updateId,
    (from..to).map { node(it, it * 2, it <= baseTo) },
    (from until to).map { edge(it, it * 2 + 1, it < baseTo) },
    zoneSetId,
)

private fun serializer(order: Order) = Vda5050Json.encodeToString(Order.serializer(), order)

/**
 * Every order update repeats the base from the stitching node and the whole horizon: the encoder formats each node
 * and edge once per order, and what goes on the wire is what the serializer gives for the whole message.
 */
class OrderEncoderTest : FunSpec({
    test(
        "each update of an order encodes to exactly the serializer's JSON, also when nodes change from horizon to base",
    ) {
        val encoder = OrderEncoder()
        val updates = listOf(
            order("o-1", 0, from = 1, baseTo = 2, to = 8),
            order("o-1", 1, from = 2, baseTo = 3, to = 8),
            order("o-1", 2, from = 3, baseTo = 5, to = 8),
            order("o-1", 3, from = 5, baseTo = 8, to = 8),
            // A new order with the same node ids: its own nodes, not the last order's.
            order("o-2", 0, from = 3, baseTo = 4, to = 6),
        )
        updates.forEach { encoder.encode(it) shouldBe serializer(it) }
    }

    test("an order without nodes or with a zone set encodes as the serializer does") {
        val encoder = OrderEncoder()
        val empty = order("o-1", 0, from = 1, baseTo = 1, to = 0)
        encoder.encode(empty) shouldBe serializer(empty)
        val zoned = order("o-1", 1, from = 1, baseTo = 2, to = 4, zoneSetId = "zones-1")
        encoder.encode(zoned) shouldBe serializer(zoned)
    }
})
