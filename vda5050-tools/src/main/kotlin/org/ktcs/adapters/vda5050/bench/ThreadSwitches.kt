package org.ktcs.adapters.vda5050.bench

import java.nio.file.Files
import java.nio.file.Path

/**
 * Context switches of a process's threads by [ThreadCpu] group, from Linux's `/proc/PID/task/TID/status`: a voluntary
 * switch is a thread going to sleep (so one wake-up later), which is what a hand-over between threads costs besides
 * the work itself.
 */
internal class ThreadSwitches(private val pid: Long) {
    private val start = read()

    /** Voluntary plus involuntary switches per group since this was created. */
    fun byGroup(): Map<String, Long> = read().entries
        .groupBy({ (_, thread) -> ThreadCpu.groupOf(thread.first) }) { (id, thread) ->
            thread.second - (start[id]?.second ?: 0L)
        }
        .mapValues { (_, switches) -> switches.sum() }

    private fun read(): Map<Long, Pair<String, Long>> {
        val tasks = runCatching { Files.list(Path.of("/proc/$pid/task")).use { it.toList() } }.getOrDefault(emptyList())
        return tasks.mapNotNull { task ->
            val id = task.fileName.toString().toLongOrNull() ?: return@mapNotNull null
            val status = runCatching {
                Files.readAllLines(task.resolve("status"))
            }.getOrNull() ?: return@mapNotNull null
            val name = status.firstOrNull {
                it.startsWith("Name:")
            }?.substringAfter(':')?.trim() ?: return@mapNotNull null
            val switches = status.filter { it.contains("ctxt_switches:") }
                .sumOf { it.substringAfter(':').trim().toLongOrNull() ?: 0L }
            id to (name to switches)
        }.toMap()
    }
}
