package org.ktcs.api.model

import org.ktcs.api.error.InvalidRequestException

/**
 * Names and property values travel in XML (the status channel, plant-model files) and JSON alike, so only characters
 * XML 1.0 can carry are accepted: tab, line feed, carriage return and everything from U+0020 on except the
 * surrogate-free non-characters U+FFFE and U+FFFF (paired surrogates are fine). Refused at creation, a name can
 * never stop a channel later. The kernel checks every name it accepts; channels use [printable] for messages.
 */
public object XmlSafeText {
    /** The first character XML cannot carry, described as `U+0001 at position 4`, or `null` if there is none. */
    public fun firstUnsafe(text: String): String? {
        var index = 0
        while (index < text.length) {
            val code = text.codePointAt(index)
            if (!isAllowed(code)) return "U+%04X at position %d".format(code, index + 1)
            index += Character.charCount(code)
        }
        return null
    }

    /** Throws [InvalidRequestException] naming [what] and the character if [text] holds one XML cannot carry. */
    public fun require(text: String, what: String) {
        firstUnsafe(text)?.let { throw InvalidRequestException("$what contains a character XML cannot carry: $it") }
    }

    /** Checks the keys and values of [properties], naming [owner] in the error. */
    public fun requireProperties(
        properties: Map<String, String>,
        owner: String,
    ): Unit = properties.forEach { (key, value) ->
        require(key, "$owner: property key '${printable(key)}'")
        require(value, "$owner: value of property '${printable(key)}'")
    }

    /** [text] with every character XML cannot carry replaced by `?`, for error messages. */
    public fun printable(text: String): String = buildString {
        text.codePoints().forEach { appendCodePoint(if (isAllowed(it)) it else '?'.code) }
    }

    private fun isAllowed(code: Int): Boolean = when {
        code == 0x9 || code == 0xA || code == 0xD -> true

        code < 0x20 -> false

        code in 0xD800..0xDFFF -> false

        // a lone surrogate; a pair arrives here as one supplementary code point
        code == 0xFFFE || code == 0xFFFF -> false

        else -> true
    }
}
