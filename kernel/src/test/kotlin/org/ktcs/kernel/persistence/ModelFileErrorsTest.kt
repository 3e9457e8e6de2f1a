package org.ktcs.kernel.persistence

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import java.io.File

/** Bad input is refused with one line that points at the problem, and nothing is half-loaded. */
class ModelFileErrorsTest : FunSpec({
    fun failure(xml: String): String {
        val error = shouldThrow<ModelFileException> { PlantModelFiles.read(xml.byteInputStream(), "bad.xml") }
        val message = error.message!!
        message.lines().size shouldBe 1
        return message
    }

    fun v7(body: String) = "<model version=\"7.0.0\" name=\"m\">\n$body\n</model>"

    val box = """<maxVehicleBoundingBox length="1" width="1" height="1" referenceOffsetX="0" referenceOffsetY="0"/>"""

    fun point(type: String = "HALT_POSITION", inner: String = box) =
        """  <point name="P" positionX="1" positionY="2" positionZ="0" type="$type">$inner</point>"""

    fun path(length: String = "1", maxVelocity: String = "1", locked: String = "false") =
        """  <path name="A" sourcePoint="P" destinationPoint="Q" length="$length" maxVelocity="$maxVelocity" """ +
            """maxReverseVelocity="0" locked="$locked"/>"""

    context("malformed XML") {
        test("names file, line, column and what the parser saw") {
            failure(v7("  <point name=\"P\">\n  </path>")) shouldBe
                "bad.xml:3:8: malformed XML: Unexpected close tag </path>; expected </point>."
        }

        test("an empty file is malformed") {
            failure("") shouldBe "bad.xml:1:0: malformed XML: Unexpected EOF in prolog"
        }

        test("text that is no XML at all is malformed") {
            failure("model: yes") shouldContain "bad.xml:1:1: malformed XML: Unexpected character 'm'"
        }

        test("a DOCTYPE is refused, so no external entity is ever read") {
            val secret = tempdir().resolve("secret.txt").apply { writeText("top secret") }
            val doctype = """<!DOCTYPE model [<!ENTITY x SYSTEM "${secret.toURI()}">]>"""
            val message = failure("<?xml version=\"1.0\"?>\n$doctype\n" + v7("""  <property name="p" value="&x;"/>"""))
            message shouldNotContain "top secret"
            message shouldBe "bad.xml:2:1: a plant model must not have a DOCTYPE"
        }
    }

    context("not a plant model of a known version") {
        test("an unsupported version is named with the supported ones") {
            failure("<model version=\"9.9.9\" name=\"m\"/>") shouldBe "bad.xml:1:1: unsupported plant model version " +
                "\"9.9.9\" (supported versions: 0.0.2, 0.0.3, 0.0.4, 0.0.5, 6.0.0, 7.0.0)"
        }

        test("a model without a version") {
            failure("\n<model name=\"m\"/>") shouldBe
                "bad.xml:2:1: <model> has no version attribute (supported versions: 0.0.2, 0.0.3, 0.0.4, 0.0.5, " +
                "6.0.0, 7.0.0)"
        }

        test("another root element") {
            failure("<?xml version=\"1.0\"?>\n<tcsOrderSet/>") shouldBe
                "bad.xml:2:1: expected root element <model> of a plant model, found <tcsOrderSet>"
        }
    }

    context("a value the schema does not allow") {
        test("an unknown enum value names the element, the attribute and the allowed values") {
            failure(v7(point(type = "FOO"))) shouldBe "bad.xml:2:3: invalid value \"FOO\" for attribute \"type\" of " +
                "<point> (expected one of HALT_POSITION, PARK_POSITION)"
        }

        test("a non-numeric length") {
            failure(v7(path(length = "long"))) shouldBe
                "bad.xml:2:3: invalid value \"long\" for attribute \"length\" of <path> " +
                "(expected a whole number that fits in 64 bits)"
        }

        test("a velocity beyond 32 bits") {
            failure(v7(path(maxVelocity = "99999999999"))) shouldBe
                "bad.xml:2:3: invalid value \"99999999999\" for attribute \"maxVelocity\" of <path> " +
                "(expected a whole number that fits in 32 bits)"
        }

        test("a boolean that is neither true nor false") {
            failure(v7(path(locked = "yes"))) shouldBe
                "bad.xml:2:3: invalid value \"yes\" for attribute \"locked\" of <path> (expected true or false)"
        }

        test("a bad value in a nested element names that element") {
            val layout = """<pointLayout labelOffsetX="-10" labelOffsetY="-20" layerId="top"/>"""
            failure(v7(point(inner = box + layout))) shouldContain
                "invalid value \"top\" for attribute \"layerId\" of <pointLayout>"
        }

        test("a missing required attribute") {
            val noSource = """  <path name="A" destinationPoint="Q" length="1" maxVelocity="1" """ +
                """maxReverseVelocity="0" locked="false"/>"""
            failure(v7(noSource)) shouldBe "bad.xml:2:3: <path> lacks the required attribute or element \"sourcePoint\""
        }

        test("a bad layout property of a 0.0.3 file names the element it belongs to") {
            val xml = """<model version="0.0.3" name="m">
                <path name="A" sourcePoint="P" destinationPoint="Q" maxVelocity="1" maxReverseVelocity="0"
                    locked="false"/>
                <visualLayout name="V" scaleX="1" scaleY="1">
                    <modelLayoutElement visualizedObjectName="A" layer="0">
                        <property name="CONN_TYPE" value="CURVY"/>
                    </modelLayoutElement>
                </visualLayout>
            </model>"""
            failure(xml) shouldBe "bad.xml: invalid layout property CONN_TYPE=\"CURVY\" in " +
                "<modelLayoutElement visualizedObjectName=\"A\">"
        }
    }

    test("a missing file is named") {
        val missing = File(tempdir(), "nowhere.xml").toPath()
        shouldThrow<ModelFileException> { PlantModelFiles.read(missing) }.message shouldBe
            "$missing: cannot read the file: no such file"
    }

    test("errors in a file name the file") {
        val file = tempdir().resolve("plant.xml").apply { writeText(v7(point(type = "FOO"))) }.toPath()
        shouldThrow<ModelFileException> { PlantModelFiles.read(file) }.message shouldContain "$file:2:3: invalid value"
    }
})
