package org.ktcs.xmlchannels.status

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement
import org.ktcs.xmlchannels.PropertyTO

// Transfer objects for ktcs-host-statuschannel.xsd; names are openTCS 4.x's.

/** `tcsStatusMessageSet`: one document per kernel change, followed by the separator. */
@JacksonXmlRootElement(localName = "tcsStatusMessageSet")
internal data class StatusMessageSetTO(
    @JacksonXmlProperty(isAttribute = true) val timeStamp: String,
    val statusMessage: List<StatusMessageTO>,
)

internal sealed interface StatusMessageTO

internal data class OrderStatusMessageTO(
    @JacksonXmlProperty(isAttribute = true, localName = "xsi:type") val xsiType: String = "orderStatusMessage",
    @JacksonXmlProperty(isAttribute = true) val orderName: String,
    @JacksonXmlProperty(isAttribute = true) val orderState: String,
    @JacksonXmlProperty(isAttribute = true) val processingVehicleName: String? = null,
    val destination: List<DestinationStatusTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
) : StatusMessageTO

internal data class DestinationStatusTO(
    @JacksonXmlProperty(isAttribute = true) val locationName: String,
    @JacksonXmlProperty(isAttribute = true) val operation: String,
    @JacksonXmlProperty(isAttribute = true) val state: String,
    val property: List<PropertyTO> = emptyList(),
)

internal data class VehicleStatusMessageTO(
    @JacksonXmlProperty(isAttribute = true, localName = "xsi:type") val xsiType: String = "vehicleStatusMessage",
    @JacksonXmlProperty(isAttribute = true) val vehicleName: String,
    @JacksonXmlProperty(isAttribute = true) val transportOrderName: String? = null,
    @JacksonXmlProperty(isAttribute = true) val position: String? = null,
    @JacksonXmlProperty(isAttribute = true) val state: String,
    @JacksonXmlProperty(isAttribute = true) val processingState: String,
    val precisePosition: PrecisePositionTO? = null,
) : StatusMessageTO

/** Millimetres. */
internal data class PrecisePositionTO(
    @JacksonXmlProperty(isAttribute = true) val x: Long,
    @JacksonXmlProperty(isAttribute = true) val y: Long,
    @JacksonXmlProperty(isAttribute = true) val z: Long,
)
