package org.ktcs.kernel.persistence

import org.w3c.dom.Element
import org.w3c.dom.Node
import org.xml.sax.InputSource
import java.io.StringReader
import java.nio.file.Path
import java.nio.file.Paths
import javax.xml.XMLConstants
import javax.xml.parsers.DocumentBuilderFactory
import javax.xml.transform.stream.StreamSource
import javax.xml.validation.Schema
import javax.xml.validation.SchemaFactory

/** Test data under src/test/resources; see fixtures/opentcs/NOTICE.md for where the openTCS files come from. */
object PersistenceFixtures {
    private const val OPENTCS = "/fixtures/opentcs"
    const val SAMPLES = "$OPENTCS/plant-models/test-samples-head"
    const val APPROVED_V7 = "$SAMPLES/ModelParserTest.readModelV7AndWriteLatestVersion.approved.xml"
    const val APPROVED_V6 = "$SAMPLES/ModelParserTest.readModelV6AndWriteLatestVersion.approved.xml"
    const val DEMO_HEAD = "$OPENTCS/plant-models/opentcs-7.5-head/Demo-01.xml"
    const val DEMO_5_0 = "$OPENTCS/plant-models/opentcs-5.0/Demo-01.xml"
    const val HANDWRITTEN_V002 = "/persistence/handwritten-0.0.2.xml"

    val openTcsModels = listOf(
        "$SAMPLES/PlantModelV004.sample.xml",
        "$SAMPLES/PlantModelV005.sample.xml",
        "$SAMPLES/PlantModelV6.sample.xml",
        "$SAMPLES/PlantModelV7.sample.xml",
        APPROVED_V6,
        APPROVED_V7,
        DEMO_HEAD,
        DEMO_5_0,
    )

    fun path(resource: String): Path =
        Paths.get(requireNotNull(PersistenceFixtures::class.java.getResource(resource)) { "missing $resource" }.toURI())

    fun text(resource: String): String = path(resource).toFile().readText()

    fun schema(version: String): Schema = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI)
        .newSchema(path("$OPENTCS/xsd/plant-model/model-$version.xsd").toFile())

    val schema7: Schema by lazy { schema("7.0.0") }

    /** Throws a SAXException naming the first violation if [xml] is not valid against [schema]. */
    fun validate(
        xml: String,
        schema: Schema = schema7,
    ) = schema.newValidator().validate(StreamSource(StringReader(xml)))
}

/**
 * The XML [text] as one line per element, attributes sorted, whitespace between elements ignored: two documents are
 * XML-equivalent if their canonical forms are equal. With [ignoreModelName] the root's `name` attribute is left out.
 */
fun canonicalXml(text: String, ignoreModelName: Boolean = false): String {
    val root = DocumentBuilderFactory.newInstance().newDocumentBuilder()
        .parse(InputSource(StringReader(text))).documentElement
    if (ignoreModelName) root.removeAttribute("name")
    return buildString { appendElement(root, 0) }
}

private fun StringBuilder.appendElement(element: Element, depth: Int) {
    val attributes = (0 until element.attributes.length).map { element.attributes.item(it) }
        .sortedBy { it.nodeName }
        .joinToString("") { " ${it.nodeName}=\"${it.nodeValue}\"" }
    append("    ".repeat(depth)).append('<').append(element.tagName).append(attributes).append(">\n")
    val children = element.childNodes
    for (i in 0 until children.length) {
        val child = children.item(i)
        when {
            child is Element -> appendElement(child, depth + 1)

            child.nodeType == Node.TEXT_NODE && child.nodeValue.isNotBlank() ->
                append("    ".repeat(depth + 1)).append(child.nodeValue.trim()).append('\n')
        }
    }
}
