package org.ktcs.xmlchannels.orders

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlRootElement
import org.ktcs.xmlchannels.PropertyTO

// Transfer objects for ktcs-host-order.xsd, ktcs-host-orderscript.xsd and ktcs-host-response.xsd. Names are the
// XSD's element and attribute names, which are openTCS 4.x's.

/** `tcsOrderSet`: the order telegram. */
@JacksonXmlRootElement(localName = ORDER_SET)
internal data class OrderSetTO(val order: List<OrderTO> = emptyList())

/**
 * `order`, both of its kinds in one class: [type] is the `xsi:type` (`transport` or `transportScript`); a
 * `transport` uses the destinations and what follows, a `transportScript` only [fileName].
 */
internal data class OrderTO(
    @JacksonXmlProperty(isAttribute = true) val id: String,
    @JacksonXmlProperty(isAttribute = true) val type: String? = null,
    @JacksonXmlProperty(isAttribute = true) val deadline: String? = null,
    @JacksonXmlProperty(isAttribute = true) val intendedVehicle: String? = null,
    @JacksonXmlProperty(isAttribute = true) val fileName: String? = null,
    val destination: List<DestinationTO> = emptyList(),
    val property: List<PropertyTO> = emptyList(),
    /** `dependency` elements: names of existing orders, as text. */
    val dependency: List<String> = emptyList(),
)

internal data class DestinationTO(
    @JacksonXmlProperty(isAttribute = true) val locationName: String,
    @JacksonXmlProperty(isAttribute = true) val operation: String,
    val property: List<PropertyTO> = emptyList(),
)

/** `tcsScriptFile`: a batch of orders in the scripts directory. */
@JacksonXmlRootElement(localName = SCRIPT_FILE)
internal data class ScriptFileTO(
    @JacksonXmlProperty(isAttribute = true) val sequentialDependencies: Boolean = false,
    val order: List<ScriptOrderTO> = emptyList(),
)

internal data class ScriptOrderTO(
    @JacksonXmlProperty(isAttribute = true) val intendedVehicle: String? = null,
    val destination: List<DestinationTO> = emptyList(),
)

/** `tcsResponseSet`: the receipt, one response per order of the telegram, in its order. */
@JacksonXmlRootElement(localName = "tcsResponseSet")
internal data class ResponseSetTO(val response: List<ResponseTO> = emptyList())

internal sealed interface ResponseTO

/**
 * `transportResponse`, and a `transport` inside a `scriptResponse` (without [xsiType]). [reason] is kTCS's addition:
 * why the order was not created.
 */
internal data class TransportResponseTO(
    @JacksonXmlProperty(isAttribute = true, localName = "xsi:type") val xsiType: String?,
    @JacksonXmlProperty(isAttribute = true) val executionSuccessful: Boolean,
    @JacksonXmlProperty(isAttribute = true) val orderName: String,
    @JacksonXmlProperty(isAttribute = true) val id: String,
    @JacksonXmlProperty(isAttribute = true) val reason: String? = null,
) : ResponseTO

/** `scriptResponse`: whether the script could be read, and a `transport` per order it created or tried to. */
internal data class ScriptResponseTO(
    @JacksonXmlProperty(isAttribute = true, localName = "xsi:type") val xsiType: String = "scriptResponse",
    @JacksonXmlProperty(isAttribute = true) val parsingSuccessful: Boolean,
    @JacksonXmlProperty(isAttribute = true) val id: String,
    @JacksonXmlProperty(isAttribute = true) val reason: String? = null,
    val transport: List<TransportResponseTO> = emptyList(),
) : ResponseTO

internal const val ORDER_SET = "tcsOrderSet"
internal const val SCRIPT_FILE = "tcsScriptFile"
internal const val TRANSPORT = "transport"
internal const val TRANSPORT_SCRIPT = "transportScript"
internal const val TRANSPORT_RESPONSE = "transportResponse"
