package org.ktcs.kernel.web.v1

import kotlinx.serialization.Serializable
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.Position
import org.ktcs.api.order.HistoryEntry

/** A property as v1 writes it in orders, sequences and status messages: `{key, value}`. */
@Serializable
data class PropertyDto(val key: String? = null, val value: String? = null)

fun Map<String, String>.toPropertyDtos(): List<PropertyDto> = map { (key, value) -> PropertyDto(key, value) }

/** The properties as a map; [field] names the list in error messages. */
fun List<PropertyDto>.toDomain(field: String): Map<String, String> = withIndex().associate { (i, property) ->
    property.key.required("$field[$i].key") to property.value.required("$field[$i].value")
}

@Serializable
data class ObjectHistoryDto(val entries: List<HistoryEntryDto>)

@Serializable
data class HistoryEntryDto(val timestamp: String, val eventCode: String, val supplements: List<String>)

/** kTCS keeps one supplement per entry; an empty one is written as no supplement. */
fun List<HistoryEntry>.toDto(): ObjectHistoryDto = ObjectHistoryDto(
    map { HistoryEntryDto(it.timestamp.toWire(), it.eventCode, listOf(it.supplement).filter(String::isNotEmpty)) },
)

@Serializable
data class CoupleDto(val x: Long, val y: Long)

fun Couple.toDto(): CoupleDto = CoupleDto(x, y)

fun CoupleDto.toDomain(): Couple = Couple(x, y)

@Serializable
data class TripleDto(val x: Long, val y: Long, val z: Long)

fun Position.toDto(): TripleDto = TripleDto(x, y, z)

fun TripleDto.toDomain(): Position = Position(x, y, z)

@Serializable
data class BoundingBoxDto(
    val length: Long = 1000,
    val width: Long = 1000,
    val height: Long = 1000,
    val referenceOffset: CoupleDto = CoupleDto(0, 0),
)

fun BoundingBox.toDto(): BoundingBoxDto = BoundingBoxDto(length, width, height, referenceOffset.toDto())

fun BoundingBoxDto.toDomain(): BoundingBox = BoundingBox(length, width, height, referenceOffset.toDomain())

@Serializable
data class AcceptableOrderTypeDto(val name: String? = null, val priority: Int? = null)
