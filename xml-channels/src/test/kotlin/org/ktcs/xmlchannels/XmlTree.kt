package org.ktcs.xmlchannels

import org.w3c.dom.Element
import java.io.ByteArrayInputStream
import javax.xml.parsers.DocumentBuilderFactory

/**
 * An XML document as a comparable tree: element names, attributes (sorted, namespace declarations left out) and
 * children; attributes named in [ignored] get the value `*`, so documents that differ only there are equal.
 */
data class XmlTree(val name: String, val attributes: Map<String, String>, val children: List<XmlTree>) {
    companion object {
        fun of(xml: String, ignored: Set<String> = emptySet()): XmlTree {
            val factory = DocumentBuilderFactory.newInstance().apply { isNamespaceAware = true }
            val document = factory.newDocumentBuilder().parse(ByteArrayInputStream(xml.toByteArray(Charsets.UTF_8)))
            return document.documentElement.toTree(ignored)
        }

        private fun Element.toTree(ignored: Set<String>): XmlTree {
            val attributes = (0 until this.attributes.length).map { this.attributes.item(it) }
                .filterNot { it.nodeName.startsWith("xmlns") }
                .associate { it.nodeName to if (it.nodeName in ignored) "*" else it.nodeValue }
            val children = (0 until childNodes.length).map { childNodes.item(it) }.filterIsInstance<Element>()
            return XmlTree(localName, attributes.toSortedMap(), children.map { it.toTree(ignored) })
        }
    }
}
