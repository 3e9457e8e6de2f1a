package org.ktcs.kernel.persistence

import com.fasterxml.jackson.annotation.JsonIgnoreProperties
import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty
import java.io.ByteArrayInputStream
import java.lang.reflect.Constructor
import java.lang.reflect.Modifier
import java.lang.reflect.ParameterizedType
import java.util.concurrent.ConcurrentHashMap
import javax.xml.stream.XMLStreamConstants.CDATA
import javax.xml.stream.XMLStreamConstants.CHARACTERS
import javax.xml.stream.XMLStreamConstants.COMMENT
import javax.xml.stream.XMLStreamConstants.END_ELEMENT
import javax.xml.stream.XMLStreamConstants.PROCESSING_INSTRUCTION
import javax.xml.stream.XMLStreamConstants.SPACE
import javax.xml.stream.XMLStreamConstants.START_ELEMENT
import javax.xml.stream.XMLStreamReader

/**
 * Reads a plant-model file straight into its transfer objects with StAX, without Jackson's data binding: Jackson
 * introspects every transfer object (with its Kotlin module, through Kotlin reflection), which was most of kTCS's
 * start-up.
 *
 * It reads only what it understands completely and gives up (`null`) on anything else: an element or attribute the
 * transfer objects have no place for, a value Jackson might read differently, a required value that is missing.
 * Jackson then reads the file as before, so warnings and error messages stay exactly Jackson's. The transfer objects
 * are Kotlin data classes: their fields, in declaration order, name the primary constructor's parameters, and
 * Kotlin's synthetic constructor fills in the defaults of those left out.
 */
internal object StreamingModelReader {
    /** [bytes] (a `<model>` document) read as [type], or `null` if Jackson has to read it. */
    fun <T : Any> read(bytes: ByteArray, type: Class<T>): T? = try {
        val reader = ModelXml.inputFactory.createXMLStreamReader(ByteArrayInputStream(bytes))
        try {
            while (reader.next() != START_ELEMENT) continue
            type.cast(readObject(reader, binding(type)))
        } finally {
            reader.close()
        }
    } catch (_: Exception) {
        null // whatever went wrong, Jackson reads the file and names the problem
    }

    private class GiveUp : Exception(null, null, false, false)

    private fun giveUp(): Nothing = throw GiveUp()

    private fun readObject(reader: XMLStreamReader, binding: Binding): Any {
        val values = arrayOfNulls<Any>(binding.properties.size)
        for (i in 0 until reader.attributeCount) {
            if (!reader.getAttributeNamespace(i).isNullOrEmpty()) giveUp()
            val name = reader.getAttributeLocalName(i)
            if (name in binding.ignored) continue
            val index = binding.attributes[name] ?: giveUp()
            values[index] = scalar(reader.getAttributeValue(i), binding.properties[index].type)
        }
        while (true) {
            when (reader.next()) {
                START_ELEMENT -> readChild(reader, binding, values)
                END_ELEMENT -> return binding.construct(values)
                CHARACTERS, CDATA -> if (!reader.isWhiteSpace) giveUp()
                COMMENT, PROCESSING_INSTRUCTION, SPACE -> continue
                else -> giveUp()
            }
        }
    }

    private fun readChild(reader: XMLStreamReader, binding: Binding, values: Array<Any?>) {
        val index = binding.elements[reader.localName] ?: giveUp()
        val property = binding.properties[index]
        val element = property.elementType
        if (element == null) {
            if (values[index] != null) giveUp()
            values[index] = readObject(reader, binding(property.type))
        } else {
            @Suppress("UNCHECKED_CAST")
            val list = values[index] as ArrayList<Any>? ?: ArrayList<Any>().also { values[index] = it }
            list += readObject(reader, binding(element))
        }
    }

    // Only spellings every reader agrees on; anything else is Jackson's to judge (or to report).
    private fun scalar(text: String, type: Class<*>): Any = when (type) {
        String::class.java -> text

        Long::class.javaPrimitiveType, Long::class.javaObjectType ->
            if (INTEGER.matches(text)) text.toLongOrNull() ?: giveUp() else giveUp()

        // As ModelXml's own Int deserializer reads them.
        Int::class.javaPrimitiveType, Int::class.javaObjectType -> text.trim().toIntOrNull() ?: giveUp()

        Boolean::class.javaPrimitiveType, Boolean::class.javaObjectType -> text.toBooleanStrictOrNull() ?: giveUp()

        // kTCS writes XML Schema's spellings of infinity.
        Double::class.javaPrimitiveType, Double::class.javaObjectType -> when (text) {
            "NaN" -> Double.NaN
            "INF" -> Double.POSITIVE_INFINITY
            "-INF" -> Double.NEGATIVE_INFINITY
            else -> if (DECIMAL.matches(text)) text.toDouble() else giveUp()
        }

        else -> if (type.isEnum) {
            type.enumConstants.firstOrNull {
                (it as Enum<*>).name == text
            } ?: giveUp()
        } else {
            giveUp()
        }
    }

    private val INTEGER = Regex("-?[0-9]{1,19}")
    private val DECIMAL = Regex("-?[0-9]{1,20}(\\.[0-9]{1,20})?([eE]-?[0-9]{1,3})?")

    private val bindings = ConcurrentHashMap<Class<*>, Binding>()

    private fun binding(type: Class<*>): Binding = bindings.getOrPut(type) { Binding.of(type) ?: giveUp() }

    private class Property(val type: Class<*>, val elementType: Class<*>?)

    private class Binding(
        private val primary: Constructor<*>,
        private val withDefaults: Constructor<*>?,
        val properties: List<Property>,
        val attributes: Map<String, Int>,
        val elements: Map<String, Int>,
        val ignored: Set<String>,
    ) {
        private val hasDefault = ConcurrentHashMap<Int, Boolean>()

        fun construct(values: Array<Any?>): Any {
            val missing = properties.indices.filter { values[it] == null }
            if (missing.isEmpty()) return primary.newInstance(*values)
            val constructor = withDefaults ?: giveUp()
            val args = arguments(values, missing)
            // A primitive without a default would silently become 0 where Jackson reports the missing value.
            if (missing.any { properties[it].type.isPrimitive && !hasDefault(it, args) }) giveUp()
            return constructor.newInstance(*args)
        }

        private fun arguments(values: Array<Any?>, missing: List<Int>): Array<Any?> {
            val masks = IntArray((properties.size + Int.SIZE_BITS - 1) / Int.SIZE_BITS)
            val args = arrayOfNulls<Any>(properties.size + masks.size + 1)
            properties.indices.forEach { args[it] = values[it] ?: zeroOf(properties[it].type) }
            missing.forEach { masks[it / Int.SIZE_BITS] = masks[it / Int.SIZE_BITS] or (1 shl (it % Int.SIZE_BITS)) }
            masks.forEachIndexed { i, mask -> args[properties.size + i] = mask }
            return args
        }

        // Kotlin ignores the argument of a parameter with a default when its mask bit is set: two different
        // arguments giving the same value means there is a default.
        private fun hasDefault(index: Int, args: Array<Any?>): Boolean = hasDefault.getOrPut(index) {
            val field = primary.declaringClass.declaredFields.filter { !Modifier.isStatic(it.modifiers) }[index]
            field.isAccessible = true
            val zero = withDefaults!!.newInstance(*args)
            val one = withDefaults.newInstance(*args.copyOf().also { it[index] = oneOf(properties[index].type) })
            field.get(zero) == field.get(one)
        }

        companion object {
            fun of(type: Class<*>): Binding? {
                val withDefaults = type.declaredConstructors.firstOrNull {
                    it.isSynthetic &&
                        it.parameterTypes.lastOrNull()?.name == "kotlin.jvm.internal.DefaultConstructorMarker"
                }
                val primary = type.declaredConstructors.filter { !it.isSynthetic }.singleOrNull() ?: return null
                val fields = type.declaredFields.filter { !Modifier.isStatic(it.modifiers) }
                if (fields.map { it.type } != primary.parameterTypes.toList()) return null
                val properties = primary.parameterTypes.zip(primary.genericParameterTypes) { raw, generic ->
                    val list = (generic as? ParameterizedType)?.takeIf { it.rawType == List::class.java }
                    Property(raw, list?.actualTypeArguments?.single() as? Class<*>)
                }
                val names = fields.mapIndexed { i, field ->
                    xmlProperty(primary, i)?.localName?.ifEmpty { null }
                        ?: field.name
                }
                val isAttribute = fields.indices.map { xmlProperty(primary, it)?.isAttribute == true }
                return Binding(
                    primary,
                    withDefaults,
                    properties,
                    names.indices.filter { isAttribute[it] }.associateBy { names[it] },
                    names.indices.filter { !isAttribute[it] }.associateBy { names[it] },
                    type.getAnnotation(JsonIgnoreProperties::class.java)?.value?.toSet().orEmpty(),
                )
            }

            private fun xmlProperty(constructor: Constructor<*>, index: Int) =
                constructor.parameterAnnotations[index].filterIsInstance<JacksonXmlProperty>().firstOrNull()
        }
    }

    private fun zeroOf(type: Class<*>): Any? = when (type) {
        Long::class.javaPrimitiveType -> 0L
        Int::class.javaPrimitiveType -> 0
        Boolean::class.javaPrimitiveType -> false
        Double::class.javaPrimitiveType -> 0.0
        else -> if (type.isPrimitive) giveUp() else null
    }

    private fun oneOf(type: Class<*>): Any = when (type) {
        Long::class.javaPrimitiveType -> 1L
        Int::class.javaPrimitiveType -> 1
        Boolean::class.javaPrimitiveType -> true
        Double::class.javaPrimitiveType -> 1.0
        else -> giveUp()
    }
}
