package org.ktcs.kernel.persistence.v004

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.kernel.persistence.NameTO
import org.ktcs.kernel.persistence.PropertyTO
import org.ktcs.kernel.persistence.v7.ColorTO
import org.ktcs.kernel.persistence.v7.LinkTO
import org.ktcs.kernel.persistence.v7.LocationTypeTO
import org.ktcs.kernel.persistence.v7.PathLayoutTO
import org.ktcs.kernel.persistence.v7.VehicleEnvelopeTO
import org.ktcs.kernel.persistence.v7.VisualLayoutTO

// Transfer objects for model-0.0.4.xsd and model-0.0.5.xsd, which differ only in two enumerations (0.0.5 dropped
// REPORT_POSITION and BEFORE_MOVEMENT). Types these schemas share with 7.0.0 are taken from the v7 package.
// The elements of 0.0.2 and 0.0.3 are subsets of these (0.0.4 only added optional parts), so the v002 package reads
// them with these classes, too; only its visual layout differs.

/** The parts of a model file that are alike from 0.0.2 to 0.0.5. */
internal interface LegacyPlantModelTO {
    val name: String
    val point: List<PointTO>
    val path: List<PathTO>
    val vehicle: List<VehicleTO>
    val locationType: List<LocationTypeTO>
    val location: List<LocationTO>
    val block: List<BlockTO>
    val property: List<PropertyTO>
}

@JacksonXmlRootElement(localName = "model")
internal data class V004PlantModelTO(
    @JacksonXmlProperty(isAttribute = true) val version: String,
    @JacksonXmlProperty(isAttribute = true) override val name: String,
    override val point: List<PointTO> = emptyList(),
    override val path: List<PathTO> = emptyList(),
    override val vehicle: List<VehicleTO> = emptyList(),
    override val locationType: List<LocationTypeTO> = emptyList(),
    override val location: List<LocationTO> = emptyList(),
    override val block: List<BlockTO> = emptyList(),
    val visualLayout: VisualLayoutTO? = null,
    override val property: List<PropertyTO> = emptyList(),
) : LegacyPlantModelTO

internal enum class PointTypeTO { REPORT_POSITION, HALT_POSITION, PARK_POSITION }

internal enum class ExecutionTriggerTO { BEFORE_MOVEMENT, AFTER_ALLOCATION, AFTER_MOVEMENT }

internal data class PointTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val xPosition: Long,
    @JacksonXmlProperty(isAttribute = true) val yPosition: Long,
    @JacksonXmlProperty(isAttribute = true) val zPosition: Long? = null,
    @JacksonXmlProperty(isAttribute = true) val vehicleOrientationAngle: Double? = null,
    @JacksonXmlProperty(isAttribute = true) val type: PointTypeTO,
    val vehicleEnvelope: List<VehicleEnvelopeTO> = emptyList(),
    val outgoingPath: List<NameTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val pointLayout: ElementLayoutTO? = null,
)

/** `pointLayoutType`; `locationLayoutType` adds [locationRepresentation]. */
internal data class ElementLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val xPosition: Long,
    @JacksonXmlProperty(isAttribute = true) val yPosition: Long,
    @JacksonXmlProperty(isAttribute = true) val xLabelOffset: Long,
    @JacksonXmlProperty(isAttribute = true) val yLabelOffset: Long,
    @JacksonXmlProperty(isAttribute = true) val locationRepresentation: LocationRepresentation? = null,
    @JacksonXmlProperty(isAttribute = true) val layerId: Int,
)

internal data class PathTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val sourcePoint: String,
    @JacksonXmlProperty(isAttribute = true) val destinationPoint: String,
    @JacksonXmlProperty(isAttribute = true) val length: Long? = null,
    @JacksonXmlProperty(isAttribute = true) val maxVelocity: Int,
    @JacksonXmlProperty(isAttribute = true) val maxReverseVelocity: Int,
    @JacksonXmlProperty(isAttribute = true) val locked: Boolean,
    val peripheralOperation: List<PeripheralOperationTO> = emptyList(),
    val vehicleEnvelope: List<VehicleEnvelopeTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val pathLayout: PathLayoutTO? = null,
)

internal data class PeripheralOperationTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val locationName: String,
    @JacksonXmlProperty(isAttribute = true) val executionTrigger: ExecutionTriggerTO,
    @JacksonXmlProperty(isAttribute = true) val completionRequired: Boolean,
)

internal data class VehicleTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val length: Long? = null,
    @JacksonXmlProperty(isAttribute = true) val energyLevelCritical: Int? = null,
    @JacksonXmlProperty(isAttribute = true) val energyLevelGood: Int? = null,
    @JacksonXmlProperty(isAttribute = true) val energyLevelFullyRecharged: Int? = null,
    @JacksonXmlProperty(isAttribute = true) val energyLevelSufficientlyRecharged: Int? = null,
    @JacksonXmlProperty(isAttribute = true) val maxVelocity: Int? = null,
    @JacksonXmlProperty(isAttribute = true) val maxReverseVelocity: Int? = null,
    @JacksonXmlProperty(isAttribute = true) val envelopeKey: String? = null,
    val property: List<PropertyTO> = emptyList(),
    val vehicleLayout: ColorTO? = null,
)

internal data class LocationTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val xPosition: Long? = null,
    @JacksonXmlProperty(isAttribute = true) val yPosition: Long? = null,
    @JacksonXmlProperty(isAttribute = true) val zPosition: Long? = null,
    @JacksonXmlProperty(isAttribute = true) val type: String,
    // Required from 0.0.4 on; 0.0.2 has it optional and 0.0.3 not at all.
    @JacksonXmlProperty(isAttribute = true) val locked: Boolean = false,
    val link: List<LinkTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val locationLayout: ElementLayoutTO? = null,
)

internal data class BlockTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val type: BlockType? = null,
    val member: List<NameTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val blockLayout: ColorTO? = null,
)
