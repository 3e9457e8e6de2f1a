package org.ktcs.kernel.persistence

import com.fasterxml.jackson.annotation.JsonInclude
import com.fasterxml.jackson.core.JsonGenerator
import com.fasterxml.jackson.core.JsonParser
import com.fasterxml.jackson.databind.DeserializationContext
import com.fasterxml.jackson.databind.DeserializationFeature
import com.fasterxml.jackson.databind.SerializationFeature
import com.fasterxml.jackson.databind.deser.std.StdScalarDeserializer
import com.fasterxml.jackson.databind.module.SimpleModule
import com.fasterxml.jackson.dataformat.xml.XmlFactory
import com.fasterxml.jackson.dataformat.xml.XmlMapper
import com.fasterxml.jackson.dataformat.xml.ser.ToXmlGenerator
import com.fasterxml.jackson.dataformat.xml.util.DefaultXmlPrettyPrinter
import org.codehaus.stax2.XMLStreamWriter2
import org.ktcs.kernel.jackson.KotlinClasses
import javax.xml.stream.XMLInputFactory
import javax.xml.stream.XMLOutputFactory

/** The one Jackson XML setup for plant-model files, and the StAX factory the version peek uses. */
internal object ModelXml {
    /** openTCS writes this exact declaration; Woodstox would use single quotes, so it is written by hand. */
    const val DECLARATION = """<?xml version="1.0" encoding="UTF-8" standalone="yes"?>"""

    val inputFactory: XMLInputFactory = XMLInputFactory.newFactory().apply {
        // Plant models never need a DTD; refusing them keeps external entities (XXE) out.
        setProperty(XMLInputFactory.SUPPORT_DTD, false)
        setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false)
    }

    /** Built on first use: reading most files needs only [inputFactory] (see StreamingModelReader). */
    val mapper: XmlMapper by lazy { newMapper() }

    private fun newMapper(): XmlMapper = KotlinClasses.configure(
        XmlMapper.builder(XmlFactory(inputFactory, XMLOutputFactory.newFactory())),
    )
        .addModule(
            SimpleModule("xsd-int")
                .addDeserializer(Int::class.javaPrimitiveType, XsdInt)
                .addDeserializer(Int::class.javaObjectType, XsdInt),
        )
        .defaultUseWrapper(false)
        // openTCS ignores what it does not know, and older versions carry elements 7.0.0 drops.
        .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
        .defaultPropertyInclusion(
            JsonInclude.Value.construct(JsonInclude.Include.NON_NULL, JsonInclude.Include.NON_NULL),
        )
        .enable(ToXmlGenerator.Feature.WRITE_XML_SCHEMA_CONFORMING_FLOATS)
        .enable(SerializationFeature.INDENT_OUTPUT)
        .defaultPrettyPrinter(DefaultXmlPrettyPrinter().apply { indentObjectsWith(FourSpaces) })
        .build()

    /** Jackson reports an `int` overflow in XML without value or attribute; this reports it like any bad value. */
    private object XsdInt : StdScalarDeserializer<Int>(Int::class.javaObjectType) {
        override fun deserialize(p: JsonParser, ctxt: DeserializationContext): Int =
            p.text.trim().toIntOrNull()
                ?: ctxt.handleWeirdStringValue(Int::class.java, p.text, "not a 32-bit integer") as Int
    }

    private object FourSpaces : DefaultXmlPrettyPrinter.Indenter {
        override fun writeIndentation(g: JsonGenerator, level: Int) = g.writeRaw("\n" + "    ".repeat(level))

        override fun writeIndentation(sw: XMLStreamWriter2, level: Int) = sw.writeRaw("\n" + "    ".repeat(level))

        override fun isInline() = false
    }
}
