package org.ktcs.kernel.scheduling

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.slf4j.LoggerFactory

class AllocateNowTest : FunSpec({
    val logger = LoggerFactory.getLogger(DefaultScheduler::class.java) as Logger
    val appender = ListAppender<ILoggingEvent>()

    beforeTest {
        appender.list.clear()
        appender.start()
        logger.addAppender(appender)
    }
    afterTest { logger.detachAppender(appender) }

    test("takes free resources at once, without a callback") {
        val f = SchedulerFixture()
        val v1 = f.client("v1")

        f.scheduler.allocateNow(v1, setOf("A"))

        f.held(v1) shouldBe setOf("A")
        f.clock.queued shouldBe 0
        appender.list.shouldBeEmpty()
    }

    test("takes a resource another client holds and warns naming both vehicles") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")

        f.scheduler.allocateNow(v2, setOf("A"))

        f.scheduler.allocations() shouldBe mapOf("v1" to setOf("A"), "v2" to setOf("A"))
        val warnings = appender.list.filter { it.level == Level.WARN }.map { it.formattedMessage }
        warnings shouldContainExactly listOf("Vehicle v2 takes A although vehicle(s) [v1] hold it")
    }

    test("a shared resource becomes free only when both holders free it") {
        val f = SchedulerFixture()
        val (v1, v2, v3) = listOf("v1", "v2", "v3").map(f::client)
        f.allocate(v1, "A")
        f.scheduler.allocateNow(v2, setOf("A"))
        f.allocate(v3, "A")

        f.free(v1, "A")
        v3.granted.shouldBeEmpty()
        f.free(v2, "A")
        v3.granted shouldContainExactly listOf(setOf("A"))
    }

    test("a client waiting for what it shares is granted once the other holder leaves") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v2, "A", "B")
        f.scheduler.allocateNow(v2, setOf("A"))

        f.free(v1, "A")

        v2.granted shouldContainExactly listOf(setOf("A", "B"))
    }
})
