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

    // Each of these names a JavaScript file that exists, so only the path check itself can refuse it.
    context("refuses paths that leave the directory or are not plain relative paths") {
        withData(
            nameFn = { "'$it'" },
            "../load-generator/panel.js",
            "../../app/main.js",
            "../statistics/chart.js",
            "./chart.js",
            "/chart.js",
            "a//chart.js",
            "..\\chart.js",
        ) { path -> files.read(path).shouldBeNull() }
    }

    context("refuses directories, missing files and unknown file types") {
        withData(nameFn = { "'$it'" }, "", "missing.js", "panel.js.bak") { path -> files.read(path).shouldBeNull() }
    }

    test("refuses a file of an unknown type even where it exists") {
        ClassPathFiles(ClassPathFilesTest::class.java.classLoader, "org/ktcs/overview")
            .read("OverviewRoutes.class").shouldBeNull()
    }
})
