package org.ktcs.overview

import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe

class ClassPathFilesTest : FunSpec({
    val files = ClassPathFiles(ClassPathFilesTest::class.java.classLoader, "org/ktcs/overview/contributions/statistics")

    test("serves a module of the directory as JavaScript") {
        val file = files.read("chart.js").shouldNotBeNull()
        file.contentType.toString() shouldBe "text/javascript; charset=UTF-8"
        String(file.bytes) shouldBe ClassPathFilesTest::class.java.getResource(
            "/org/ktcs/overview/contributions/statistics/chart.js",
        )!!.readText()
    }

    context("refuses paths that leave the directory, directories and unknown file types") {
        withData(
            nameFn = { "'$it'" },
            "../load-generator/panel.js",
            "./chart.js",
            "/chart.js",
            "a//chart.js",
            "..\\chart.js",
            "",
            "missing.js",
            "../../../../META-INF/services/org.ktcs.kernel.extension.KtcsExtension",
            "../../OverviewRoutes.class",
        ) { path -> files.read(path).shouldBeNull() }
    }
})
