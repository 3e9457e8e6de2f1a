package org.ktcs.kernel.dispatching

/**
 * Why [vehicle] cannot do an order, for the order's history.
 *
 * @property detail the reason, phrased for one vehicle ("does not accept type 'Transport'").
 * @property summary the reason phrased for all vehicles, when each gave the same [detail]
 *   ("no vehicle accepts type 'Transport'").
 */
internal data class Refusal(val vehicle: String, val detail: String, val summary: String = "all vehicles: $detail")

/**
 * One line for an order's history that explains [refusals]: the shared summary when every vehicle gave the same
 * reason, otherwise the first few reasons by vehicle name. Sorted, so the same refusals always read the same.
 */
internal fun describe(refusals: Collection<Refusal>): String {
    val sorted = refusals.distinct().sortedBy { it.vehicle }
    val first = sorted.first()
    if (sorted.size > 1 && sorted.all { it.detail == first.detail }) return first.summary
    val shown = sorted.take(MAX_SHOWN).joinToString("; ") { "vehicle ${it.vehicle}: ${it.detail}" }
    return if (sorted.size > MAX_SHOWN) "$shown; and ${sorted.size - MAX_SHOWN} more vehicles" else shown
}

private const val MAX_SHOWN = 3
