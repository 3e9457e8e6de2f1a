package org.ktcs.kernel.web.plugins

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import io.ktor.client.request.get
import io.ktor.client.statement.bodyAsText
import io.ktor.http.HttpStatusCode
import io.ktor.server.testing.testApplication
import io.mockk.coEvery
import org.ktcs.kernel.web.KernelVersion
import org.ktcs.kernel.web.WebOptions
import org.ktcs.kernel.web.docs.quietServices
import org.ktcs.kernel.web.webModule
import org.slf4j.LoggerFactory

/**
 * Ktor's StatusPages builds a TRACE line naming the handler of every error answer, whether TRACE is on or not. A
 * lambda's name is rendered through Kotlin reflection, which made an unknown order's 404 cost half as much again:
 * the answers name themselves.
 */
class ErrorAnswerNamesTest : FunSpec({
    val logger = LoggerFactory.getLogger("io.ktor.server.plugins.statuspages") as Logger
    val appender = ListAppender<ILoggingEvent>()

    beforeTest {
        appender.list.clear()
        appender.start()
        logger.addAppender(appender)
        logger.level = Level.TRACE
    }
    afterTest {
        logger.detachAppender(appender)
        logger.level = null
    }

    test("an unknown name's 404 and an unrouted path's 404 are answered by handlers with cheap names") {
        val services = quietServices()
        coEvery { services.transportOrders.transportOrder(any()) } returns null
        testApplication {
            application { webModule(KernelVersion("test"), services, WebOptions()) }
            val unknown = client.get("/v1/transportOrders/Nope")
            unknown.status shouldBe HttpStatusCode.NotFound
            unknown.bodyAsText() shouldBe """["unknown transport order 'Nope'"]"""
            val unrouted = client.get("/v1/nothingHere")
            unrouted.status shouldBe HttpStatusCode.NotFound
            unrouted.bodyAsText() shouldBe """["no such resource: GET /v1/nothingHere"]"""
        }
        val executed = appender.list.map { it.formattedMessage }.filter { it.startsWith("Executing ") }
        executed.map { it.substringBefore(" for ") } shouldContainAll
            listOf("Executing answer to ObjectUnknownException", "Executing answer to status 404")
    }
})
