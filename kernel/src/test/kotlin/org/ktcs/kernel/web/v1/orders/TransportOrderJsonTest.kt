package org.ktcs.kernel.web.v1.orders

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.types.shouldBeSameInstanceAs
import io.ktor.utils.io.ByteChannel
import io.ktor.utils.io.readRemaining
import kotlinx.io.readByteArray
import kotlinx.serialization.builtins.ListSerializer
import kotlinx.serialization.json.Json
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.web.v1.V1Json
import java.time.Instant

class TransportOrderJsonTest : FunSpec({
    fun order(name: String) = TransportOrder(
        name = name,
        driveOrders = listOf(DriveOrder("Drive-1", Destination("Storage 01", "Load cargo"))),
        state = TransportOrderState.DISPATCHABLE,
        creationTime = Instant.EPOCH,
        history = listOf(HistoryEntry(Instant.EPOCH, "tcs:history:orderCreated")),
    )

    fun encoded(order: TransportOrder) = V1Json.json.encodeToString(TransportOrderDto.serializer(), order.toDto())

    test("an order's JSON is exactly what encoding its DTO gives, and is encoded once per version") {
        val cache = TransportOrderJson()
        val order = order("T1")

        val first = cache.of(order)

        first.decodeToString() shouldBe encoded(order)
        cache.of(order) shouldBeSameInstanceAs first
    }

    test("the cached JSON changes when the order changes") {
        val cache = TransportOrderJson()
        val order = order("T1")
        val before = cache.of(order).decodeToString()
        val assigned = order.copy(state = TransportOrderState.BEING_PROCESSED, processingVehicle = "Vehicle-01")

        val after = cache.of(assigned).decodeToString()

        after shouldNotBe before
        after shouldBe encoded(assigned)
        // An equal copy is another version as far as the cache knows: it is encoded again, to the same JSON.
        cache.of(assigned.copy()).decodeToString() shouldBe after
    }

    test("a list is the JSON array of the orders' DTOs, and forgets orders that left the pool") {
        val cache = TransportOrderJson()
        val orders = listOf(order("T1"), order("T2"), order("T3"))
        cache.list(orders, wholePool = true)

        val listed = cache.list(orders.drop(1), wholePool = true).toByteArray().decodeToString()

        Json.parseToJsonElement(listed) shouldBe V1Json.json.encodeToJsonElement(
            ListSerializer(TransportOrderDto.serializer()),
            orders.drop(1).map { it.toDto() },
        )
        cache.size shouldBe 2
        cache.list(emptyList(), wholePool = false).toByteArray().decodeToString() shouldBe "[]"
    }

    test("orders gone from the kernel leave the cache though no one lists the whole pool") {
        val cache = TransportOrderJson()
        val kept = order("Kept")
        cache.of(kept)
        // Created and answered once each (as POST does), then swept: nothing but the cache knows them.
        repeat(200) { cache.of(order("Swept-$it")) }

        val deadline = System.nanoTime() + 10_000_000_000L
        while (cache.size > 1 && System.nanoTime() < deadline) {
            System.gc()
            Thread.sleep(10)
        }

        cache.size shouldBe 1
        cache.of(kept).decodeToString() shouldBe encoded(kept)
    }

    test("a list is written to the connection part by part as exactly the bytes its Content-Length announces") {
        val cache = TransportOrderJson()
        for (orders in listOf(emptyList(), listOf(order("T1")), listOf(order("T1"), order("T2"), order("T3")))) {
            val content = cache.list(orders, wholePool = true)
            val channel = ByteChannel()

            content.writeTo(channel)
            channel.flushAndClose()
            val written = channel.readRemaining().readByteArray()

            written shouldBe content.toByteArray()
            written.size.toLong() shouldBe content.contentLength
            Json.parseToJsonElement(written.decodeToString()) shouldBe V1Json.json.encodeToJsonElement(
                ListSerializer(TransportOrderDto.serializer()),
                orders.map { it.toDto() },
            )
        }
    }
})
