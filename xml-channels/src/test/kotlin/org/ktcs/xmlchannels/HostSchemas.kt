package org.ktcs.xmlchannels

import java.io.StringReader
import javax.xml.XMLConstants
import javax.xml.transform.stream.StreamSource
import javax.xml.validation.Schema
import javax.xml.validation.SchemaFactory

/** The module's XSDs, for checking what the channels read and write. */
object HostSchemas {
    val order = load("ktcs-host-order.xsd")
    val orderScript = load("ktcs-host-orderscript.xsd")
    val response = load("ktcs-host-response.xsd")
    val status = load("ktcs-host-statuschannel.xsd")

    /** Throws [org.xml.sax.SAXException] naming the first violation. */
    fun Schema.validate(xml: String) = newValidator().validate(StreamSource(StringReader(xml)))

    private fun load(name: String): Schema {
        val url = checkNotNull(HostSchemas::class.java.getResource("/org/ktcs/xmlchannels/xsd/$name")) { name }
        return SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI).newSchema(url)
    }
}

/** A test resource's text. */
fun sample(name: String): String =
    checkNotNull(HostSchemas::class.java.getResource("/org/ktcs/xmlchannels/samples/$name")) { name }.readText()
