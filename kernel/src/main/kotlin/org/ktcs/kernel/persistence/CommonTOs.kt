package org.ktcs.kernel.persistence

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty

// Transfer objects whose XSD type is the same in every schema version from 0.0.2 to 7.0.0.

/** `propertyType`. */
internal data class PropertyTO(
    @JacksonXmlProperty(isAttribute = true) val name: String,
    @JacksonXmlProperty(isAttribute = true) val value: String,
)

/** Any element that only carries a `name` attribute: `outgoingPath`, `member`, `allowedOperation`, … */
internal data class NameTO(@JacksonXmlProperty(isAttribute = true) val name: String)

/** `vertexType` and `controlPointType`. */
internal data class CoupleTO(
    @JacksonXmlProperty(isAttribute = true) val x: Long,
    @JacksonXmlProperty(isAttribute = true) val y: Long,
)

/** Properties as openTCS reads them: a later duplicate name wins. */
internal fun List<PropertyTO>.toMap(): Map<String, String> = associate { it.name to it.value }

/** Properties as openTCS writes them: sorted by name. */
internal fun Map<String, String>.toPropertyTOs(): List<PropertyTO> =
    entries.sortedBy { it.key }.map { PropertyTO(it.key, it.value) }

internal fun Collection<String>.toSortedNameTOs(): List<NameTO> = sorted().map(::NameTO)
