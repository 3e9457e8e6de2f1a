package org.ktcs.kernel.bench

/**
 * Where a process's CPU went between two samples of [ProcStats.threads], by kind of thread: threads whose names differ
 * only in digits (`DefaultDispatcher-worker-3`, `C1 CompilerThre0`) count as one kind. A thread that ended between
 * the samples is missing from the second one, so its share is lost; a thread that started counts from zero.
 */
object ThreadCpu {
    /** CPU seconds per kind of thread between [before] and [after], largest first. */
    fun byKind(
        before: Map<Long, Pair<String, Double>>,
        after: Map<Long, Pair<String, Double>>,
    ): List<Pair<String, Double>> =
        after.entries
            .groupBy({ kind(it.value.first) }) { (id, thread) -> thread.second - (before[id]?.second ?: 0.0) }
            .mapValues { (_, seconds) -> seconds.sum() }
            .filterValues { it > 0.0 }
            .toList()
            .sortedByDescending { it.second }

    /** A thread's name with its digits replaced by `#`, so that a pool's threads count as one kind. */
    fun kind(name: String): String = name.replace(Regex("[0-9]+"), "#")
}
