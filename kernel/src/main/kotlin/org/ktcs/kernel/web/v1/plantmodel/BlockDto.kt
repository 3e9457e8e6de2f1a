package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockLayout
import org.ktcs.api.model.BlockType
import org.ktcs.kernel.web.v1.parseEnum
import org.ktcs.kernel.web.v1.required

@Serializable
data class BlockDto(
    val name: String? = null,
    val type: String = "SINGLE_VEHICLE_ONLY",
    val layout: BlockLayoutDto = BlockLayoutDto(),
    val memberNames: List<String> = emptyList(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

@Serializable
data class BlockLayoutDto(val color: String = "#FF0000")

fun Block.toDto(): BlockDto =
    BlockDto(name, type.name, BlockLayoutDto(layout.color), members.toList(), properties.toPlantProperties())

fun BlockDto.toDomain(field: String): Block = Block(
    name = name.required("$field.name"),
    type = parseEnum<BlockType>(type, "$field.type"),
    members = memberNames.toSet(),
    layout = BlockLayout(layout.color),
    properties = properties.toDomain("$field.properties"),
)
