package org.ktcs.xmlchannels.reliability

import kotlin.random.Random

/** Generates order channel telegrams from a seed: valid ones for the demo plant, and every kind of broken one. */
class TelegramGenerator(seed: Long) {
    private val random = Random(seed)

    fun next(): ByteArray = when (random.nextInt(100)) {
        in 0..24 -> valid().toByteArray()
        in 25..44 -> mutated(valid()).toByteArray()
        in 45..54 -> bytesFlipped(valid().toByteArray())
        in 55..62 -> valid().toByteArray().let { it.copyOf(random.nextInt(it.size)) }
        in 63..70 -> xml11(valid(hostileText())).toByteArray()
        in 71..76 -> script().toByteArray()
        in 77..82 -> hostileDocument().toByteArray()
        in 83..88 -> valid(hostileText()).toByteArray()
        else -> ByteArray(random.nextInt(0, 512)) { random.nextInt(256).toByte() }
    }

    private fun valid(text: String = "v"): String = buildString {
        append("""<?xml version="1.0" encoding="UTF-8"?>""")
        append("<tcsOrderSet>")
        repeat(random.nextInt(1, 4)) { index ->
            append("""<order xsi:type="transport" id="${escape(pick("O-$index", text))}" """)
            if (random.nextInt(4) == 0) append("""intendedVehicle="${escape(pick("Vehicle-01", "Ghost", text))}" """)
            if (random.nextInt(4) == 0) append("""deadline="${escape(pick("2030-01-01T00:00:00Z", "soon", text))}" """)
            append("""xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">""")
            repeat(random.nextInt(1, 3)) {
                val (location, operation) = pick(*DESTINATIONS)
                append("""<destination locationName="${escape(location)}" operation="${escape(operation)}"/>""")
            }
            if (random.nextBoolean()) append("""<property key="${escape(pick("k", text))}" value="${escape(text)}"/>""")
            append("</order>")
        }
        append("</tcsOrderSet>")
    }

    /** XML 1.1 lets character references carry control characters that XML 1.0 (the receipt) cannot. */
    private fun xml11(telegram: String): String = telegram.replace("version=\"1.0\"", "version=\"1.1\"")
        .replace("value=\"", "value=\"a&#x${random.nextInt(1, 0x20).toString(16)};")

    private fun mutated(telegram: String): String = when (random.nextInt(10)) {
        0 -> telegram.replace("tcsOrderSet", pick("tcsScriptFile", "tcsResponseSet", "html"))
        1 -> telegram.replace("id=\"", "ID=\"")
        2 -> telegram.replace("xsi:type=\"transport\"", "xsi:type=\"${pick("transportScript", "teleport", "")}\"")
        3 -> telegram.replace("</order>", "<order>".repeat(random.nextInt(1, 200)))
        4 -> telegram.replace("<destination ", "<destination locationName=\"dup\" ")
        5 -> telegram.replace("Storage 01", "x".repeat(random.nextInt(1, 50_000)))
        6 -> telegram.replace("<tcsOrderSet>", "<tcsOrderSet>" + "<x>".repeat(5_000))
        7 -> telegram + "\r\n\r\n" + telegram
        8 -> telegram.replace("UTF-8", pick("ISO-8859-1", "UTF-16", "EBCDIC", "nonsense"))
        else -> telegram.replace("<destination ", "<destination ${text()}=\"1\" ")
    }

    private fun bytesFlipped(bytes: ByteArray): ByteArray = bytes.copyOf().also { copy ->
        repeat(random.nextInt(1, 8)) { copy[random.nextInt(copy.size)] = random.nextInt(256).toByte() }
    }

    private fun script(): String =
        """<?xml version="1.0" encoding="UTF-8"?><tcsOrderSet><order xsi:type="transportScript" id="S" """ +
            """fileName="${escape(
                pick("template.tcs", "../../../etc/passwd", "/etc/hostname", "missing.tcs", "", hostileText()),
            )}" """ +
            """xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"/></tcsOrderSet>"""

    private fun hostileDocument(): String = pick(
        """<?xml version="1.0"?><!DOCTYPE tcsOrderSet [<!ENTITY x SYSTEM "file:///etc/passwd">]><tcsOrderSet>&x;</tcsOrderSet>""",
        """<?xml version="1.0"?><!DOCTYPE a [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]><tcsOrderSet>&b;</tcsOrderSet>""",
        "<tcsOrderSet>" + "<order>".repeat(10_000),
        "",
        "\r\n\r\n",
        "<tcsOrderSet/>",
        "<?xml version=\"1.0\"?><tcsOrderSet><![CDATA[" + "x".repeat(1000) + "]]></tcsOrderSet>",
        "<?xml-stylesheet href=\"http://evil.example/x.xsl\"?><tcsOrderSet/>",
    )

    private fun hostileText(): String = pick(
        "Ctl-" + random.nextInt(1, 0x20).toChar() + "x",
        "a|b",
        "<&>",
        "日本語",
        "\uFFFE",
        "x".repeat(random.nextInt(1, 3000)),
        "",
    )

    private fun text(): String = pick("foo", "bar", "xsi:nil", "x${random.nextInt(100)}")

    private fun escape(text: String): String =
        text.replace("&", "&amp;").replace("<", "&lt;").replace("\"", "&quot;")

    private fun <T> pick(vararg options: T): T = options[random.nextInt(options.size)]

    private companion object {
        val DESTINATIONS = arrayOf(
            "Storage 01" to "Load cargo",
            "Goods out 01" to "Unload cargo",
            "Point-0001" to "MOVE",
            "Storage 99" to "Load cargo",
            "Storage 01" to "Drill",
        )
    }
}
