package org.ktcs.kernel.bench

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import java.time.Instant
import java.time.format.DateTimeParseException

/**
 * When the kernel itself finished a batch: the latest `finishedTime` (the kernel's clock) of the batch's orders. The
 * bench's own figure ends when its client *saw* the last order finish; on a machine whose cores the client shares
 * with kTCS the client may read the event stream behind, and the difference says how much of a makespan was the
 * client's lateness rather than the kernel's.
 */
internal object KernelFinishTimes {
    /**
     * The latest finish of the FINISHED orders whose names start with [prefix], `null` if none or no answer; an answer
     * that is no list of orders with ISO-8601 finish times fails with a message that says so.
     */
    fun lastFinished(client: BenchClient, prefix: String): Instant? {
        val text = client.get("/transportOrders") ?: return null
        return try {
            Json.parseToJsonElement(text).jsonArray.asSequence()
                .map { it.jsonObject }
                .filter { it.string("name")?.startsWith(prefix) == true && it.string("state") == "FINISHED" }
                .mapNotNull { order -> order.string("finishedTime")?.let(Instant::parse) }
                .maxOrNull()
        } catch (error: IllegalArgumentException) {
            // kotlinx's SerializationException (malformed JSON) and its casts (no array, no objects) both are ones.
            throw IllegalStateException("GET /transportOrders answered no list of orders: ${error.message}", error)
        } catch (error: DateTimeParseException) {
            throw IllegalStateException(
                "GET /transportOrders answered a finishedTime that is no instant: ${error.message}",
                error,
            )
        }
    }
}
