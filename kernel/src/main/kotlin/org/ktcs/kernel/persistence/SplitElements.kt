package org.ktcs.kernel.persistence

import org.w3c.dom.Element
import org.w3c.dom.Node
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import javax.xml.XMLConstants
import javax.xml.parsers.DocumentBuilderFactory
import javax.xml.stream.XMLStreamConstants.END_ELEMENT
import javax.xml.stream.XMLStreamConstants.START_ELEMENT
import javax.xml.stream.XMLStreamException
import javax.xml.transform.TransformerFactory
import javax.xml.transform.dom.DOMSource
import javax.xml.transform.stream.StreamResult

/**
 * openTCS reads an element's children in any order, but Jackson keeps only the last run of a repeated element: a
 * vehicle's `<property>`s before and after its `<boundingBox>` would lose the first ones (`tcs:preferredAdapterClass`
 * among them). Files with such split runs get their repeated children moved together (in document order) before
 * decoding, with a warning per split; other files are decoded as they are, so line numbers in errors stay exact.
 */
internal object SplitElements {
    fun regroup(bytes: ByteArray, source: String, warnings: ReadWarnings): ByteArray {
        val splits = findSplits(bytes, source)
        if (splits.isEmpty()) return bytes
        splits.forEach { warnings.note(source, it) }
        return regrouped(bytes)
    }

    private fun findSplits(bytes: ByteArray, source: String): List<String> {
        val reader = ModelXml.inputFactory.createXMLStreamReader(ByteArrayInputStream(bytes))
        val stack = ArrayDeque<Frame>()
        val splits = mutableListOf<String>()
        try {
            while (reader.hasNext()) {
                when (reader.next()) {
                    START_ELEMENT -> {
                        val name = reader.localName
                        stack.lastOrNull()?.child(name)?.let { parent ->
                            splits += "<$name> elements of $parent are not together (again at line " +
                                "${reader.location.lineNumber}); all of them are read"
                        }
                        stack.addLast(Frame(describe(name, reader.getAttributeValue(null, "name"))))
                    }

                    END_ELEMENT -> stack.removeLast()
                }
            }
        } catch (e: XMLStreamException) {
            throw malformed(source, e)
        } finally {
            reader.close()
        }
        return splits
    }

    private fun describe(element: String, name: String?) = if (name == null) {
        "<$element>"
    } else {
        "<$element name=\"$name\">"
    }

    /** Tracks one open element's children; [child] answers the element's description when [name] comes back. */
    private class Frame(val description: String) {
        private val seen = HashSet<String>()
        private var last: String? = null
        private val reported = HashSet<String>()

        fun child(name: String): String? {
            val split = name != last && name in seen && reported.add(name)
            seen += name
            last = name
            return if (split) description else null
        }
    }

    private fun regrouped(bytes: ByteArray): ByteArray {
        val factory = DocumentBuilderFactory.newInstance().apply {
            setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true)
            setFeature("http://apache.org/xml/features/disallow-doctype-decl", true)
        }
        val document = factory.newDocumentBuilder().parse(ByteArrayInputStream(bytes))
        regroupChildren(document.documentElement)
        val out = ByteArrayOutputStream()
        TransformerFactory.newInstance().newTransformer().transform(DOMSource(document), StreamResult(out))
        return out.toByteArray()
    }

    private fun regroupChildren(element: Element) {
        val children = element.childNodes.let { nodes -> (0 until nodes.length).map { nodes.item(it) } }
            .filterIsInstance<Element>()
        children.forEach(::regroupChildren)
        val byName = children.groupBy { it.tagName }
        if (byName.values.all { group -> group.isContiguousIn(children) }) return
        children.forEach { element.removeChild(it) }
        byName.values.flatten().forEach { element.appendChild(it) }
    }

    private fun List<Node>.isContiguousIn(children: List<Element>): Boolean {
        val first = children.indexOf(first())
        return children.subList(first, first + size) == this
    }
}
