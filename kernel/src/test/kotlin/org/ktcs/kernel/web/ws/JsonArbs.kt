package org.ktcs.kernel.web.ws

import io.kotest.property.Arb
import io.kotest.property.RandomSource
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.arbitrary.take
import java.time.Instant

/** What the hand-written JSON writers' tests make their objects of: text and instants that JSON makes hard. */
internal object JsonArbs {
    private val pieces = listOf(
        "a", "Z", "0", " ", "-", "\"", "\\", "/", "\u0000", "\u0001", "\b", "\t", "\n", "\u000B", "\u000C", "\r",
        "\u001F", "\u007F", "\u0080", "é", "Ä", "ߐ", "→", "€", "\u2028", "\uFFFF", "😀", "\uD83D", "\uDE00",
        "\"claimedResources\":[]", "\"driveOrders\":[]", "\"history\":{", "null", "NaN", ",", "}", "]",
    )

    // Any UTF-16 units, lone surrogates among them.
    private val anyChars = Arb.list(Arb.int(0..0xFFFF), 0..8).map { codes ->
        codes.map { it.toChar() }.joinToString("")
    }

    /** Strings of quotes, backslashes, control characters, non-ASCII, emoji, lone surrogates and JSON's punctuation. */
    val text = Arb.choice(Arb.list(Arb.element(pieces), 0..6).map { it.joinToString("") }, anyChars)

    /** Instants from far past to far future, `Instant.MIN` and `Instant.MAX` among them. */
    val instant = Arb.choice(
        Arb.element(Instant.EPOCH, Instant.MIN, Instant.MAX, Instant.parse("2024-02-29T23:59:59.123Z")),
        arbitrary {
            Instant.ofEpochSecond(Arb.long(-MAX_SECONDS..MAX_SECONDS).bind(), Arb.long(0L..MAX_NANOS).bind())
        },
    )

    /** [arb]'s values, half of them from a few made once: objects that several states share, as copies do. */
    fun <T> shared(arb: Arb<T>, poolSize: Int = 3): Arb<T> =
        Arb.choice(Arb.element(arb.take(poolSize, RandomSource.seeded(poolSize.toLong())).toList()), arb)

    private const val MAX_SECONDS = 100_000_000_000L
    private const val MAX_NANOS = 999_999_999L
}
