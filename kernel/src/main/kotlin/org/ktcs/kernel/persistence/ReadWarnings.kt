package org.ktcs.kernel.persistence

import com.fasterxml.jackson.core.JsonParser
import com.fasterxml.jackson.databind.DeserializationContext
import com.fasterxml.jackson.databind.JsonDeserializer
import com.fasterxml.jackson.databind.deser.DeserializationProblemHandler
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser
import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.validation.ModelProblem
import org.ktcs.kernel.validation.Severity

/**
 * A plant model as read from a file, with what the reader skipped or changed on the way.
 *
 * @property warnings one [Severity.WARNING] per kind of thing skipped or changed, naming it.
 */
data class ModelRead(val model: PlantModel, val warnings: List<ModelProblem>)

/** Collects the reader's warnings for one file; confined to the thread reading it. */
internal class ReadWarnings(private val source: String) {
    private val skipped = LinkedHashMap<Pair<String, String>, Skipped>()
    private val notes = mutableListOf<ModelProblem>()

    /** Jackson calls this for every attribute or element the transfer objects have no place for. */
    val handler: DeserializationProblemHandler = object : DeserializationProblemHandler() {
        override fun handleUnknownProperty(
            ctxt: DeserializationContext,
            p: JsonParser,
            deserializer: JsonDeserializer<*>?,
            beanOrClass: Any?,
            propertyName: String,
        ): Boolean {
            val owner = elementName(beanOrClass)
            val line = (p as? FromXmlParser)?.staxReader?.location?.lineNumber ?: p.currentLocation().lineNr
            skipped.getOrPut(owner to propertyName) { Skipped(line) }.count++
            p.skipChildren()
            return true
        }
    }

    /** Records a change the reader made to the file's content, e.g. coordinates it had to pick between. */
    fun note(element: String, message: String) {
        notes += ModelProblem(Severity.WARNING, element, message)
    }

    fun all(): List<ModelProblem> = skipped.map { (key, skip) ->
        val (owner, name) = key
        val times = if (skip.count > 1) " (${skip.count} times)" else ""
        val line = if (skip.line > 0) " at line ${skip.line}" else ""
        ModelProblem(Severity.WARNING, source, "ignored unknown '$name' in <$owner>$line$times")
    } + notes

    private class Skipped(val line: Int) {
        var count = 0
    }

    private fun elementName(beanOrClass: Any?): String {
        val type = beanOrClass as? Class<*> ?: beanOrClass?.javaClass ?: return "?"
        val name = type.simpleName.removeSuffix("TO").removePrefix("V7").removePrefix("V004").removePrefix("V002")
        return if (name == "PlantModel") "model" else name.replaceFirstChar { it.lowercase() }
    }
}
