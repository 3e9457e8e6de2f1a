package org.ktcs.kernel.bench

import java.io.PrintStream
import java.util.Locale

/**
 * The figures of several runs of a workload, in the order they were first recorded. One run prints `name: value`;
 * several print `name: median (min …, max …, runs N)`.
 */
class Figures {
    private val values = LinkedHashMap<String, MutableList<Double>>()
    private val texts = LinkedHashMap<String, String>()

    /** Records [value] of [name] for the current run; `null` (not measurable here) is left out. */
    fun record(name: String, value: Double?) {
        if (value == null || value.isNaN()) return
        values.getOrPut(name) { mutableListOf() } += value
    }

    /** Records a figure that is text (the plant, the process measured), printed as it is. */
    fun note(name: String, text: String) {
        texts[name] = text
    }

    fun print(out: PrintStream) {
        texts.forEach { (name, text) -> out.println("$name: $text") }
        values.forEach { (name, list) -> out.println("$name: ${summary(list)}") }
    }

    private fun summary(list: List<Double>): String {
        val sorted = list.sorted()
        val median = if (sorted.size % 2 == 1) {
            sorted[sorted.size / 2]
        } else {
            (sorted[sorted.size / 2 - 1] + sorted[sorted.size / 2]) / 2
        }
        if (sorted.size == 1) return format(median)
        return "${format(median)} (min ${format(sorted.first())}, max ${format(sorted.last())}, runs ${sorted.size})"
    }

    private fun format(value: Double): String = when {
        value == Math.rint(value) && kotlin.math.abs(value) < 1e12 -> value.toLong().toString()
        kotlin.math.abs(value) >= 100 -> String.format(Locale.ROOT, "%.1f", value)
        else -> String.format(Locale.ROOT, "%.3f", value)
    }
}

/** The [fraction] quantile (0..1) of [samples] by the nearest-rank method, `null` if there are none. */
fun quantile(samples: List<Double>, fraction: Double): Double? {
    if (samples.isEmpty()) return null
    val sorted = samples.sorted()
    val rank = kotlin.math.ceil(fraction * sorted.size).toInt().coerceIn(1, sorted.size)
    return sorted[rank - 1]
}
