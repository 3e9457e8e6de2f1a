package org.ktcs.adapters.loopback

/** Why a message was not carried out, e.g. a missing or unusable parameter; the text names the problem. */
internal class MessageRejectedException(message: String) : Exception(message)

/** Typed access to a message's parameters; each getter takes the accepted names, the preferred one first. */
internal class MessageParameters(val all: Map<String, String>) {
    fun optional(vararg names: String): String? = names.firstNotNullOfOrNull { all[it] }

    fun string(vararg names: String): String =
        optional(*names) ?: throw MessageRejectedException("parameter '${names.first()}' is missing")

    fun long(vararg names: String): Long = parse(names, "a whole number") { it.toLongOrNull() }

    fun double(vararg names: String): Double = parse(names, "a number") {
        it.toDoubleOrNull()?.takeIf(Double::isFinite)
    }

    fun boolean(vararg names: String): Boolean = parse(names, "true or false") {
        it.lowercase().toBooleanStrictOrNull()
    }

    fun percent(vararg names: String): Double {
        val value = double(*names)
        if (value !in 0.0..100.0) {
            throw MessageRejectedException("parameter '${names.first()}' must be 0 to 100, was $value")
        }
        return value
    }

    fun positive(vararg names: String): Double {
        val value = double(*names)
        if (value <= 0.0) throw MessageRejectedException("parameter '${names.first()}' must be above 0, was $value")
        return value
    }

    fun <E : Enum<E>> oneOf(values: Array<E>, vararg names: String): E =
        parse(names, "one of ${values.joinToString()}") { text -> values.firstOrNull { it.name.equals(text, true) } }

    private fun <T : Any> parse(names: Array<out String>, expected: String, convert: (String) -> T?): T {
        val text = string(*names)
        return convert(text.trim())
            ?: throw MessageRejectedException("parameter '${names.first()}' must be $expected, was '$text'")
    }
}
