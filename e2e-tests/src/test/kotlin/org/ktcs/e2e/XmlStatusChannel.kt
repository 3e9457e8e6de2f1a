package org.ktcs.e2e

import java.net.Socket
import kotlin.time.Duration.Companion.seconds

/** Reads the XML status channel until every order in [names] was reported FINISHED, or two minutes passed. */
fun Socket.finishedOrders(names: Set<String>): Set<String> {
    val finished = mutableSetOf<String>()
    val text = StringBuilder()
    val reader = getInputStream().bufferedReader()
    val deadline = System.nanoTime() + 120.seconds.inWholeNanoseconds
    val chunk = CharArray(8192)
    while (!finished.containsAll(names) && System.nanoTime() < deadline) {
        val read = reader.read(chunk)
        if (read < 0) break
        text.append(chunk, 0, read)
        Regex("orderName=\"([^\"]+)\" orderState=\"FINISHED\"").findAll(text).forEach { finished += it.groupValues[1] }
    }
    return finished.intersect(names)
}
