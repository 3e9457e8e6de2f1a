package org.ktcs.kernel.dispatching

/**
 * The best of [candidates] by [ranking] that [assess] accepts (returning it routed), routing as few as possible:
 * candidates are tried in the order [CandidateRanking.beforeRouting] gives them, one group of equally ranked ones at a
 * time, and the search stops at the first group with an accepted candidate. With keys that need no route (the
 * default `BY_DEADLINE`, `BY_AGE`, …) every group holds one candidate, so the first acceptable one wins.
 */
internal fun bestCandidate(
    candidates: List<Candidate>,
    ranking: CandidateRanking,
    assess: (Candidate) -> Candidate?,
): Candidate? {
    if (candidates.isEmpty()) return null
    // Most searches end with the first group: find it without sorting a vehicle's candidates among thousands of orders.
    val best = candidates.minWith(ranking.beforeRouting)
    val (first, rest) = candidates.partition { ranking.beforeRouting.compare(it, best) == 0 }
    val accepted = first.mapNotNull(assess)
    if (accepted.isNotEmpty()) return accepted.minWith(ranking.full)
    val sorted = rest.sortedWith(ranking.beforeRouting)
    var start = 0
    while (start < sorted.size) {
        val end = groupEnd(sorted, start, ranking.beforeRouting)
        val accepted = sorted.subList(start, end).mapNotNull(assess)
        if (accepted.isNotEmpty()) return accepted.minWith(ranking.full)
        start = end
    }
    return null
}

private fun groupEnd(sorted: List<Candidate>, start: Int, comparator: Comparator<Candidate>): Int {
    var end = start + 1
    while (end < sorted.size && comparator.compare(sorted[start], sorted[end]) == 0) end++
    return end
}
