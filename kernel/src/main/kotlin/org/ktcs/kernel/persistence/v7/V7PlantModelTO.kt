package org.ktcs.kernel.persistence.v7

import com.fasterxml.jackson.annotation.JsonIgnoreProperties
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.kernel.persistence.CoupleTO
import org.ktcs.kernel.persistence.NameTO
import org.ktcs.kernel.persistence.PropertyTO

// Transfer objects for model-7.0.0.xsd, also used to read 6.0.0, which differs only by the layout positions.
// Property names are the XSD's element and attribute names; constructor order is the order openTCS writes them in.
// The XSD enumerations are spelled exactly like the domain enums, so those serve as TO enums here.

@JacksonXmlRootElement(localName = "model")
internal data class V7PlantModelTO(
    @JacksonXmlProperty(isAttribute = true) val version: String,
    @JacksonXmlProperty(isAttribute = true) val name: String,
    val point: List<PointTO> = emptyList(),
    val path: List<PathTO> = emptyList(),
    val vehicle: List<VehicleTO> = emptyList(),
    val locationType: List<LocationTypeTO> = emptyList(),
    val location: List<LocationTO> = emptyList(),
    val block: List<BlockTO> = emptyList(),
    val visualLayout: VisualLayoutTO? = null,
    val property: List<PropertyTO> = emptyList(),
)

internal data class BoundingBoxTO(
    @JacksonXmlProperty(isAttribute = true) val length: Long,
    @JacksonXmlProperty(isAttribute = true) val width: Long,
    @JacksonXmlProperty(isAttribute = true) val height: Long,
    @JacksonXmlProperty(isAttribute = true) val referenceOffsetX: Long,
    @JacksonXmlProperty(isAttribute = true) val referenceOffsetY: Long,
)

internal data class VehicleEnvelopeTO(
    @JacksonXmlProperty(isAttribute = true) val key: String,
    val vertex: List<CoupleTO> = emptyList(),
)

internal data class LocationTypeTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    val allowedOperation: List<NameTO> = emptyList(),
    val allowedPeripheralOperation: List<NameTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val locationTypeLayout: LocationTypeLayoutTO? = null,
)

internal data class LocationTypeLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val locationRepresentation: LocationRepresentation,
)

internal data class LocationTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val positionX: Long,
    @JacksonXmlProperty(isAttribute = true) val positionY: Long,
    @JacksonXmlProperty(isAttribute = true) val positionZ: Long,
    @JacksonXmlProperty(isAttribute = true) val locked: Boolean,
    @JacksonXmlProperty(isAttribute = true) val type: String,
    val link: List<LinkTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val locationLayout: LocationLayoutTO? = null,
)

internal data class LinkTO(
    @JacksonXmlProperty(isAttribute = true) val point: String,
    val allowedOperation: List<NameTO> = emptyList(),
)

/** 6.0.0 also has `positionX`/`positionY` here; 7.0.0 dropped them. */
@JsonIgnoreProperties("positionX", "positionY")
internal data class LocationLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val labelOffsetX: Long,
    @JacksonXmlProperty(isAttribute = true) val labelOffsetY: Long,
    @JacksonXmlProperty(isAttribute = true) val locationRepresentation: LocationRepresentation,
    @JacksonXmlProperty(isAttribute = true) val layerId: Int,
)

internal data class BlockTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val type: BlockType,
    val member: List<NameTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    val blockLayout: ColorTO? = null,
)

/** `blockLayoutType` and `vehicleLayoutType`. */
internal data class ColorTO(@JacksonXmlProperty(isAttribute = true) val color: String)

internal data class VisualLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val scaleX: Double,
    @JacksonXmlProperty(isAttribute = true) val scaleY: Double,
    val layer: List<LayerTO> = emptyList(),
    val layerGroup: List<LayerGroupTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
)

internal data class LayerTO(
    @JacksonXmlProperty(isAttribute = true) val id: Int,
    @JacksonXmlProperty(isAttribute = true) val ordinal: Int,
    @JacksonXmlProperty(isAttribute = true) val visible: Boolean,
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val groupId: Int,
)

internal data class LayerGroupTO(
    @JacksonXmlProperty(isAttribute = true) val id: Int,
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val visible: Boolean,
)
