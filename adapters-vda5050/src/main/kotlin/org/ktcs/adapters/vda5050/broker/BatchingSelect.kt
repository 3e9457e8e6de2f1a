package org.ktcs.adapters.vda5050.broker

import io.netty.channel.SelectStrategy
import io.netty.channel.SelectStrategyFactory

/**
 * How the builtin broker's event loop waits for its clients: after each round of work it pauses [windowMillis] before
 * it looks again, so the messages that arrived meanwhile are read in one round instead of each waking the thread on
 * its own. A hundred vehicles send about 1,100 messages a second, one by one: without the pause each is a wake-up of
 * the thread (a context switch and a round of the event loop); with 5 ms there are at most 200. A message waits at most
 * [windowMillis] longer; one that arrives while the broker is idle is read at once. 0: no pause.
 */
internal class BatchingSelect(private val windowMillis: Long) : SelectStrategyFactory {
    override fun newSelectStrategy() = SelectStrategy { readyNow, hasTasks ->
        when {
            hasTasks -> readyNow.get()

            windowMillis == 0L -> SelectStrategy.SELECT

            else -> {
                Thread.sleep(windowMillis)
                readyNow.get().takeIf { it > 0 } ?: SelectStrategy.SELECT
            }
        }
    }
}
