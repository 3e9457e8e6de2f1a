package org.ktcs.extension.config

/**
 * One configuration key with its type, default and meaning. kTCS declares its own in the kernel's `KtcsSettings`,
 * an extension in [org.ktcs.extension.KtcsExtension.settings]; the documented config file and the README's
 * configuration table are checked against both.
 */
public class Setting<T : Any>(
    public val key: String,
    public val default: T,
    public val description: String,
    private val parser: (String) -> T?,
    private val constraint: Constraint<T> = Constraint.none(),
) {
    /** Parses [raw] or throws [ConfigException] naming this key, the value and what is expected. */
    public fun parse(raw: String, source: String): T {
        val value = parser(raw.trim())
            ?: throw ConfigException("$source: bad value '$raw' for $key: expected ${typeName()}")
        constraint.problem(value)?.let { throw ConfigException("$source: bad value '$raw' for $key: $it") }
        return value
    }

    /** The default as it is written in a config file. */
    public fun defaultText(): String = default.toString()

    private fun typeName(): String = when (default) {
        is Int -> "a whole number"
        is Double -> "a number"
        is Boolean -> "true or false"
        is Long -> "a whole number"
        is Enum<*> -> "one of " + default.javaClass.enumConstants.joinToString(", ")
        is EnumList<*> -> "a comma-separated list of " + default.values.first().javaClass.enumConstants.joinToString()
        else -> "a text"
    }

    override fun toString(): String = key
}

/** A rule a parsed value must follow, with a description for the error message. */
public fun interface Constraint<T> {
    /** Why [value] is not acceptable, or `null` if it is. */
    public fun problem(value: T): String?

    public companion object {
        public fun <T> none(): Constraint<T> = Constraint { null }

        public fun intRange(range: IntRange): Constraint<Int> =
            Constraint { if (it in range) null else "must be between ${range.first} and ${range.last}" }

        public fun positive(): Constraint<Double> =
            Constraint { if (it > 0.0 && it.isFinite()) null else "must be a positive number" }

        public fun notBlank(): Constraint<String> = Constraint { if (it.isNotBlank()) null else "must not be empty" }
    }
}

public fun intSetting(key: String, default: Int, range: IntRange, description: String): Setting<Int> =
    Setting(key, default, description, String::toIntOrNull, Constraint.intRange(range))

public fun positiveDoubleSetting(key: String, default: Double, description: String): Setting<Double> =
    Setting(key, default, description, String::toDoubleOrNull, Constraint.positive())

public fun stringSetting(key: String, default: String, description: String): Setting<String> =
    Setting(key, default, description, { it }, Constraint.notBlank())

public fun booleanSetting(key: String, default: Boolean, description: String): Setting<Boolean> =
    Setting(key, default, description, String::toBooleanStrictOrNull)

public fun longSetting(key: String, default: Long, range: LongRange, description: String): Setting<Long> =
    Setting(key, default, description, String::toLongOrNull, inRange(range.first, range.last))

public fun doubleSetting(
    key: String,
    default: Double,
    range: ClosedFloatingPointRange<Double>,
    description: String,
): Setting<Double> = Setting(
    key,
    default,
    description,
    String::toDoubleOrNull,
    inRange(range.start, range.endInclusive),
)

private fun <T : Comparable<T>> inRange(low: T, high: T): Constraint<T> =
    Constraint { if (it in low..high) null else "must be between $low and $high" }

/** A comma-separated list of enum constants, e.g. `IDLE_FIRST,BY_ENERGY_LEVEL`; written back the same way. */
public inline fun <reified E : Enum<E>> enumListSetting(
    key: String,
    default: List<E>,
    description: String,
): Setting<EnumList<E>> =
    Setting(key, EnumList(default), description, { raw ->
        val names = raw.split(',').map(String::trim).filter(String::isNotEmpty)
        val values = names.map { name -> enumValues<E>().firstOrNull { it.name.equals(name, ignoreCase = true) } }
        if (names.isEmpty() || values.any { it == null }) null else EnumList(values.filterNotNull())
    })

/** A list of enum constants that prints as the config file writes it. */
public data class EnumList<E : Enum<E>>(public val values: List<E>) {
    override fun toString(): String = values.joinToString(",")
}

public inline fun <reified E : Enum<E>> enumSetting(key: String, default: E, description: String): Setting<E> =
    Setting(key, default, description, { raw ->
        enumValues<E>().firstOrNull { it.name.equals(raw, ignoreCase = true) }
    })
