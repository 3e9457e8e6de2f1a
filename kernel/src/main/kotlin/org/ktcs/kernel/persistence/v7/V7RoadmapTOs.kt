package org.ktcs.kernel.persistence.v7

import com.fasterxml.jackson.annotation.JsonIgnoreProperties
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.ExecutionTrigger
import org.ktcs.api.model.PointType
import org.ktcs.kernel.persistence.CoupleTO
import org.ktcs.kernel.persistence.NameTO
import org.ktcs.kernel.persistence.PropertyTO

// Points, paths and vehicles of model-7.0.0.xsd (see V7PlantModelTO.kt).

internal data class PointTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val positionX: Long,
    @JacksonXmlProperty(isAttribute = true) val positionY: Long,
    @JacksonXmlProperty(isAttribute = true) val positionZ: Long,
    @JacksonXmlProperty(isAttribute = true) val vehicleOrientationAngle: Double? = null,
    @JacksonXmlProperty(isAttribute = true) val type: PointType,
    val maxVehicleBoundingBox: BoundingBoxTO,
    val vehicleEnvelope: List<VehicleEnvelopeTO> = emptyList(),
    val outgoingPath: List<NameTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val pointLayout: PointLayoutTO? = null,
)

/** 6.0.0 also has `positionX`/`positionY` here; 7.0.0 dropped them. */
@JsonIgnoreProperties("positionX", "positionY")
internal data class PointLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val labelOffsetX: Long,
    @JacksonXmlProperty(isAttribute = true) val labelOffsetY: Long,
    @JacksonXmlProperty(isAttribute = true) val layerId: Int,
)

internal data class PathTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val sourcePoint: String,
    @JacksonXmlProperty(isAttribute = true) val destinationPoint: String,
    @JacksonXmlProperty(isAttribute = true) val length: Long,
    @JacksonXmlProperty(isAttribute = true) val maxVelocity: Int,
    @JacksonXmlProperty(isAttribute = true) val maxReverseVelocity: Int,
    @JacksonXmlProperty(isAttribute = true) val locked: Boolean,
    val peripheralOperation: List<PeripheralOperationTO> = emptyList(),
    val vehicleEnvelope: List<VehicleEnvelopeTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val pathLayout: PathLayoutTO? = null,
)

internal data class PeripheralOperationTO(
    @JacksonXmlProperty(isAttribute = true) val completionRequired: Boolean,
    @JacksonXmlProperty(isAttribute = true) val executionTrigger: ExecutionTrigger,
    @JacksonXmlProperty(isAttribute = true) val locationName: String,
    @JacksonXmlProperty(isAttribute = true) val name: String,
)

internal data class PathLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val connectionType: ConnectionType,
    @JacksonXmlProperty(isAttribute = true) val layerId: Int,
    val controlPoint: List<CoupleTO> = emptyList(),
)

internal data class VehicleTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val energyLevelCritical: Int,
    @JacksonXmlProperty(isAttribute = true) val energyLevelGood: Int,
    @JacksonXmlProperty(isAttribute = true) val energyLevelFullyRecharged: Int,
    @JacksonXmlProperty(isAttribute = true) val energyLevelSufficientlyRecharged: Int,
    @JacksonXmlProperty(isAttribute = true) val maxVelocity: Int,
    @JacksonXmlProperty(isAttribute = true) val maxReverseVelocity: Int,
    @JacksonXmlProperty(isAttribute = true) val envelopeKey: String? = null,
    val boundingBox: BoundingBoxTO,
    val property: List<PropertyTO> = emptyList(),
    val vehicleLayout: ColorTO? = null,
)
