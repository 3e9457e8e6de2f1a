package org.ktcs.xmlchannels

import com.fasterxml.jackson.annotation.JsonInclude
import com.fasterxml.jackson.annotation.JsonSetter
import com.fasterxml.jackson.annotation.Nulls
import com.fasterxml.jackson.databind.DeserializationContext
import com.fasterxml.jackson.databind.DeserializationFeature
import com.fasterxml.jackson.databind.deser.DeserializationProblemHandler
import com.fasterxml.jackson.databind.exc.MismatchedInputException
import com.fasterxml.jackson.dataformat.xml.XmlFactory
import com.fasterxml.jackson.dataformat.xml.XmlMapper
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import com.fasterxml.jackson.dataformat.xml.ser.ToXmlGenerator
import com.fasterxml.jackson.module.paramnames.ParameterNamesModule
import java.io.ByteArrayInputStream
import javax.xml.stream.XMLInputFactory
import javax.xml.stream.XMLOutputFactory

/** The one Jackson XML setup for the host interface's telegrams, scripts and status messages. */
internal object HostXml {
    /** openTCS writes this exact declaration; Woodstox would use single quotes, so it is written by hand. */
    const val DECLARATION = """<?xml version="1.0" encoding="UTF-8" standalone="yes"?>"""

    private val inputFactory: XMLInputFactory = XMLInputFactory.newFactory().apply {
        // Telegrams come from the network: no DTDs, so no external entities (XXE) and no entity expansion bombs.
        setProperty(XMLInputFactory.SUPPORT_DTD, false)
        setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false)
    }

    // The transfer objects' defaults are all null, false or an empty list, which plain Jackson gives them too:
    // constructor parameter names (-java-parameters) are all it needs, and no kotlin-reflect.
    val mapper: XmlMapper = XmlMapper.builder(XmlFactory(inputFactory, XMLOutputFactory.newFactory()))
        .addModule(ParameterNamesModule())
        .withConfigOverride(List::class.java) { it.setterInfo = JsonSetter.Value.forValueNulls(Nulls.AS_EMPTY) }
        .addHandler(MissingValues)
        .defaultUseWrapper(false)
        // openTCS's JAXB binding ignored what it did not know; so do we.
        .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
        .defaultPropertyInclusion(
            JsonInclude.Value.construct(JsonInclude.Include.NON_NULL, JsonInclude.Include.NON_NULL),
        )
        // Writes a property named "xsi:type" as the XML Schema instance attribute, as openTCS's receipts carry it.
        .enable(ToXmlGenerator.Feature.AUTO_DETECT_XSI_TYPE)
        .build()

    /**
     * The local name of the root element of a well-formed document; throws [javax.xml.stream.XMLStreamException]
     * naming the first error otherwise. Checked up front, so that Jackson's errors only mean a wrong structure.
     */
    fun wellFormedRootName(bytes: ByteArray): String {
        val reader = inputFactory.createXMLStreamReader(ByteArrayInputStream(bytes))
        try {
            reader.nextTag()
            val root = reader.localName
            while (reader.hasNext()) reader.next()
            return root
        } finally {
            reader.close()
        }
    }

    inline fun <reified T> read(bytes: ByteArray): T = mapper.readValue(bytes, T::class.java)

    /** [value] as a document with openTCS's declaration. */
    fun write(value: Any): String = DECLARATION + "\n" + mapper.writeValueAsString(value)

    /** A required value left out fails Kotlin's null check in the constructor: reported as missing, by name. */
    private object MissingValues : DeserializationProblemHandler() {
        override fun handleInstantiationProblem(
            ctxt: DeserializationContext,
            instClass: Class<*>,
            argument: Any?,
            t: Throwable,
        ): Any {
            val parameter = generateSequence(t) { it.cause }.filterIsInstance<NullPointerException>().firstOrNull()
                ?.message?.takeIf { it.startsWith("Parameter specified as non-null is null") }
                ?.substringAfterLast("parameter ", "")?.ifEmpty { null }
                ?: return NOT_HANDLED
            throw MismatchedInputException.from(ctxt.parser, instClass, "missing required value '$parameter'")
                .apply { prependPath(instClass, parameter) }
        }
    }
}

/** `property`: a key and a value, on orders and destinations. */
internal data class PropertyTO(
    @JacksonXmlProperty(isAttribute = true) val key: String,
    @JacksonXmlProperty(isAttribute = true) val value: String,
)

/** Properties as openTCS reads them: a later duplicate key wins. */
internal fun List<PropertyTO>.toMap(): Map<String, String> = associate { it.key to it.value }

/** Properties sorted by key, so that messages are stable. */
internal fun Map<String, String>.toPropertyTOs(): List<PropertyTO> =
    entries.sortedBy { it.key }.map { PropertyTO(it.key, it.value) }
