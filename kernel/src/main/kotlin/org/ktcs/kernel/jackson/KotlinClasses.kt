package org.ktcs.kernel.jackson

import com.fasterxml.jackson.annotation.JsonCreator
import com.fasterxml.jackson.annotation.JsonSetter
import com.fasterxml.jackson.annotation.Nulls
import com.fasterxml.jackson.databind.BeanDescription
import com.fasterxml.jackson.databind.DeserializationConfig
import com.fasterxml.jackson.databind.DeserializationContext
import com.fasterxml.jackson.databind.cfg.MapperBuilder
import com.fasterxml.jackson.databind.cfg.MapperConfig
import com.fasterxml.jackson.databind.deser.SettableBeanProperty
import com.fasterxml.jackson.databind.deser.ValueInstantiator
import com.fasterxml.jackson.databind.deser.ValueInstantiators
import com.fasterxml.jackson.databind.deser.impl.PropertyValueBuffer
import com.fasterxml.jackson.databind.deser.std.StdValueInstantiator
import com.fasterxml.jackson.databind.exc.MismatchedInputException
import com.fasterxml.jackson.databind.introspect.Annotated
import com.fasterxml.jackson.databind.introspect.NopAnnotationIntrospector
import com.fasterxml.jackson.databind.module.SimpleModule
import com.fasterxml.jackson.module.paramnames.ParameterNamesModule
import java.lang.reflect.Constructor
import java.lang.reflect.InvocationTargetException
import java.lang.reflect.Modifier
import java.util.concurrent.ConcurrentHashMap

/**
 * Jackson binding of Kotlin classes without kotlin-reflect (jackson-module-kotlin needs it, and with it on the class
 * path every `typeOf` at start-up builds full reflection descriptors: a tenth of kTCS's memory after start).
 *
 * A Kotlin class is created through its primary constructor, whose parameter names the compiler keeps
 * (`-java-parameters`, read by [ParameterNamesModule]). What the input leaves out takes the parameter's Kotlin
 * default, through the synthetic constructor Kotlin generates for defaults; a left-out value without default (or a
 * `null` for a non-null parameter) is a [MismatchedInputException] "missing required value" that names the
 * parameter, as jackson-module-kotlin reported it; a `null` list, set or map is empty.
 */
internal object KotlinClasses {
    fun <B : MapperBuilder<*, B>> configure(builder: B): B = builder
        .addModule(ParameterNamesModule())
        .addModule(DefaultsModule)
        .apply {
            for (type in listOf(List::class.java, Set::class.java, Map::class.java, Collection::class.java)) {
                withConfigOverride(type) { it.setterInfo = JsonSetter.Value.forValueNulls(Nulls.AS_EMPTY) }
            }
        }

    private object DefaultsModule : SimpleModule("kotlin-defaults") {
        override fun setupModule(context: SetupContext) {
            super.setupModule(context)
            context.insertAnnotationIntrospector(PrimaryConstructors)
            context.addValueInstantiators(
                object : ValueInstantiators.Base() {
                    override fun findValueInstantiator(
                        config: DeserializationConfig,
                        beanDesc: BeanDescription,
                        defaultInstantiator: ValueInstantiator,
                    ): ValueInstantiator = DefaultsInstantiator.of(defaultInstantiator) ?: defaultInstantiator
                },
            )
        }
    }

    /** Marks a Kotlin class's primary constructor as its creator, as jackson-module-kotlin does. */
    private object PrimaryConstructors : NopAnnotationIntrospector() {
        override fun findCreatorAnnotation(config: MapperConfig<*>, a: Annotated): JsonCreator.Mode? {
            val constructor = a.annotated as? Constructor<*> ?: return null
            return JsonCreator.Mode.PROPERTIES.takeIf { constructor.parameterCount > 0 && isPrimary(constructor) }
        }
    }

    private fun isKotlinClass(type: Class<*>): Boolean =
        type.isAnnotationPresent(Metadata::class.java) && !type.isEnum && !type.isInterface

    /** The constructor whose defaults [withDefaults] fills in, or the class's only one. */
    private fun isPrimary(constructor: Constructor<*>): Boolean {
        val type = constructor.declaringClass
        if (constructor.isSynthetic || !isKotlinClass(type)) return false
        val withDefaults = withDefaults(type)
        return if (withDefaults != null) {
            val count = constructor.parameterCount
            withDefaults.parameterCount == count + (count + Int.SIZE_BITS - 1) / Int.SIZE_BITS + 1 &&
                withDefaults.parameterTypes.take(count) == constructor.parameterTypes.toList()
        } else {
            type.declaredConstructors.count { !it.isSynthetic } == 1
        }
    }

    /** Kotlin's constructor for defaults: the parameters, one bit mask per 32 of them, a `DefaultConstructorMarker`. */
    private fun withDefaults(type: Class<*>): Constructor<*>? = type.declaredConstructors.firstOrNull {
        it.isSynthetic && it.parameterTypes.lastOrNull()?.name == "kotlin.jvm.internal.DefaultConstructorMarker"
    }

    private class DefaultsInstantiator(
        delegate: ValueInstantiator,
        private val primary: Constructor<*>,
        private val withDefaults: Constructor<*>?,
    ) : ValueInstantiator.Delegating(delegate) {
        private val hasDefault = ConcurrentHashMap<Int, Boolean>()

        override fun createFromObjectWith(
            ctxt: DeserializationContext,
            props: Array<SettableBeanProperty>,
            buffer: PropertyValueBuffer,
        ): Any? {
            val args = buffer.getParameters(props)
            val absent = props.indices.filter { !buffer.hasParameter(props[it]) }
            absent.forEach { if (args[it] == null) args[it] = zeroOf(primary.parameterTypes[it]) }
            // Jackson gives a left-out number 0 (and a left-out reference null, which Kotlin's null check reports).
            absent.firstOrNull { primary.parameterTypes[it].isPrimitive && !hasDefault(it, args, absent) }
                ?.let { throw missing(ctxt, props[it].name) }
            return try {
                if (absent.isEmpty() || withDefaults == null) {
                    primary.newInstance(*args)
                } else {
                    withDefaults.newInstance(*arguments(args, absent))
                }
            } catch (e: InvocationTargetException) {
                val cause = e.cause ?: e
                val parameter = nullParameter(cause) ?: return ctxt.handleInstantiationProblem(valueClass, args, cause)
                throw missing(ctxt, parameter)
            }
        }

        private fun arguments(args: Array<Any?>, absent: List<Int>): Array<Any?> {
            val masks = IntArray((args.size + Int.SIZE_BITS - 1) / Int.SIZE_BITS)
            absent.forEach { masks[it / Int.SIZE_BITS] = masks[it / Int.SIZE_BITS] or (1 shl (it % Int.SIZE_BITS)) }
            return arrayOf(*args, *masks.toTypedArray(), null)
        }

        // Kotlin ignores the argument of a parameter with a default when its mask bit is set: if two different
        // arguments make equal objects, there is a default. Asked once per parameter; a probe the other values make
        // fail (the constructor refuses them) answers nothing and is not kept.
        private fun hasDefault(index: Int, args: Array<Any?>, absent: List<Int>): Boolean {
            val withDefaults = withDefaults ?: return false
            hasDefault[index]?.let { return it }
            val one = args.copyOf().also { it[index] = oneOf(primary.parameterTypes[index]) }
            return runCatching {
                fieldsOf(withDefaults.newInstance(*arguments(args, absent))) ==
                    fieldsOf(withDefaults.newInstance(*arguments(one, absent)))
            }.onSuccess { hasDefault[index] = it }.getOrDefault(false)
        }

        private fun fieldsOf(value: Any): List<Any?> = value.javaClass.declaredFields
            .filter { !Modifier.isStatic(it.modifiers) }
            .map {
                it.isAccessible = true
                it.get(value)
            }

        private fun zeroOf(type: Class<*>): Any? = primitive(type, 0)

        private fun oneOf(type: Class<*>): Any? = primitive(type, 1)

        /** [number] as a value of the primitive [type]; `null` for any other type. */
        private fun primitive(type: Class<*>, number: Int): Any? = when (type) {
            Long::class.javaPrimitiveType -> number.toLong()
            Int::class.javaPrimitiveType -> number
            Boolean::class.javaPrimitiveType -> number != 0
            Double::class.javaPrimitiveType -> number.toDouble()
            Float::class.javaPrimitiveType -> number.toFloat()
            Short::class.javaPrimitiveType -> number.toShort()
            Byte::class.javaPrimitiveType -> number.toByte()
            Char::class.javaPrimitiveType -> number.toChar()
            else -> null
        }

        companion object {
            fun of(instantiator: ValueInstantiator): ValueInstantiator? {
                if (instantiator !is StdValueInstantiator || !instantiator.canCreateFromObjectWith()) return null
                val primary = instantiator.withArgsCreator?.annotated as? Constructor<*> ?: return null
                if (!isPrimary(primary)) return null
                primary.isAccessible = true
                val withDefaults = withDefaults(primary.declaringClass)?.also { it.isAccessible = true }
                return DefaultsInstantiator(instantiator, primary, withDefaults)
            }
        }
    }

    /** The parameter named by Kotlin's null check of a non-null parameter, if [error] is one. */
    private fun nullParameter(error: Throwable): String? = (error as? NullPointerException)?.message
        ?.takeIf { it.startsWith("Parameter specified as non-null is null") }
        ?.substringAfterLast("parameter ", "")
        ?.ifEmpty { null }

    private fun missing(ctxt: DeserializationContext, name: String): MismatchedInputException =
        MismatchedInputException.from(ctxt.parser, null as Class<*>?, "missing required value '$name'").apply {
            prependPath(null, name)
        }
}
