package org.ktcs.kernel.web.ws

import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.SseVehicleDto
import org.ktcs.kernel.web.v1.events.toSseDto

/**
 * Vehicles' event states as UTF-8 JSON, their resource lists spliced in as bytes. A driving vehicle changes many times
 * a second while the resources it claimed for its route (most of its JSON on a large plant) stay the same list, and a
 * client that keeps the latest state leaves them out when they did not change (`omitUnchanged`): the vehicle is encoded
 * with its lists empty, and each list ([EncodedResourceLists]), made only when a client takes it, is copied in.
 */
internal class EncodedVehicles(capacity: Int) {
    private val claimed = EncodedResourceLists(capacity)
    private val allocated = EncodedResourceLists(capacity)

    fun marked(vehicle: Vehicle): MarkedJson {
        val text = utf8(V1Json.json.encodeToString(SseVehicleDto.serializer(), vehicle.toSseDto(withResources = false)))
        return Marked(
            text,
            lazy { claimed.of(vehicle.name, vehicle.claimedResources) },
            lazy { allocated.of(vehicle.name, vehicle.allocatedResources) },
        )
    }

    /** A vehicle's JSON with empty resource lists ([text]), and the lists' bytes, made when first needed. */
    private class Marked(
        private val text: ByteArray,
        claimed: Lazy<ByteArray>,
        allocated: Lazy<ByteArray>,
    ) : MarkedJson {
        private val lists = mapOf("claimedResources" to claimed::value, "allocatedResources" to allocated::value)

        override val full: ByteArray by lazy { rewriteFields(text, emptyList(), lists) }

        override fun without(fields: List<String>): ByteArray = rewriteFields(text, fields, lists)
    }
}

/** An object's state as UTF-8 JSON, whole or without some of its top-level fields. */
internal interface MarkedJson {
    /** The whole object. */
    val full: ByteArray

    /** The object without its top-level [fields]. */
    fun without(fields: List<String>): ByteArray
}
