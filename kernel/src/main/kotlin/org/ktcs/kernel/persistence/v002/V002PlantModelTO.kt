package org.ktcs.kernel.persistence.v002

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement
import org.ktcs.kernel.persistence.PropertyTO
import org.ktcs.kernel.persistence.v004.BlockTO
import org.ktcs.kernel.persistence.v004.LegacyPlantModelTO
import org.ktcs.kernel.persistence.v004.LocationTO
import org.ktcs.kernel.persistence.v004.PathTO
import org.ktcs.kernel.persistence.v004.PointTO
import org.ktcs.kernel.persistence.v004.VehicleTO
import org.ktcs.kernel.persistence.v7.LocationTypeTO

// Transfer objects for model-0.0.2.xsd (openTCS 4.x) and model-0.0.3.xsd (openTCS 5.0). Their elements are read
// with the 0.0.4 classes (see V004PlantModelTO.kt); only the visual layout differs: it holds a
// `modelLayoutElement` with drawing properties per element instead of layout children of the elements.
// What 7.0.0 cannot hold is not declared here, so reading skips it; ModelLayoutElements.kt lists it.

@JacksonXmlRootElement(localName = "model")
internal data class V002PlantModelTO(
    @JacksonXmlProperty(isAttribute = true) val version: String,
    @JacksonXmlProperty(isAttribute = true) override val name: String,
    override val point: List<PointTO> = emptyList(),
    override val path: List<PathTO> = emptyList(),
    override val vehicle: List<VehicleTO> = emptyList(),
    override val locationType: List<LocationTypeTO> = emptyList(),
    override val location: List<LocationTO> = emptyList(),
    override val block: List<BlockTO> = emptyList(),
    val visualLayout: List<V002VisualLayoutTO> = emptyList(),
    override val property: List<PropertyTO> = emptyList(),
) : LegacyPlantModelTO

internal data class V002VisualLayoutTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val scaleX: Double,
    @JacksonXmlProperty(isAttribute = true) val scaleY: Double,
    val modelLayoutElement: List<ModelLayoutElementTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
)

internal data class ModelLayoutElementTO(
    @JacksonXmlProperty(isAttribute = true) val visualizedObjectName: String,
    @JacksonXmlProperty(isAttribute = true) val layer: Long,
    val property: List<PropertyTO> = emptyList(),
)
