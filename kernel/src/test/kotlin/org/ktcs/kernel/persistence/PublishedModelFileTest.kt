package org.ktcs.kernel.persistence

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.kernel.app.PlantModelLoader
import java.nio.file.Files

class PublishedModelFileTest : FunSpec({
    val demo = PlantModelLoader.loadDemo().model

    test("saving creates the directory, writes the file as the writer does and leaves no temporary file behind") {
        val directory = tempdir().toPath().resolve("data")
        val published = PublishedModelFile(directory)

        published.save(demo)

        Files.readString(published.file) shouldBe PlantModelFiles.writeToString(demo)
        Files.exists(published.backup) shouldBe false
        Files.list(directory).use { files -> files.map { it.fileName.toString() }.toList() } shouldBe
            listOf(PublishedModelFile.FILE_NAME)
    }

    test("a save that fails names the file and leaves the published model as it was, without temporary files") {
        val directory = tempdir().toPath()
        val published = PublishedModelFile(directory)
        published.save(demo.copy(name = "First"))
        // Something in the backup's way (as root, a read-only directory would not stop the write).
        Files.createDirectories(published.backup.resolve("in-the-way"))

        val error = shouldThrow<ModelFileException> { published.save(demo.copy(name = "Second")) }

        error.message shouldContain published.file.toString()
        PlantModelFiles.read(published.file).name shouldBe "First"
        Files.list(directory).use { files -> files.map { it.fileName.toString() }.sorted().toList() } shouldBe
            listOf(PublishedModelFile.FILE_NAME, "${PublishedModelFile.FILE_NAME}.bak")
    }

    test("the second save keeps the first model as the backup") {
        val published = PublishedModelFile(tempdir().toPath())
        published.save(demo.copy(name = "First"))
        published.save(demo.copy(name = "Second"))
        PlantModelFiles.read(published.file).name shouldBe "Second"
        PlantModelFiles.read(published.backup).name shouldBe "First"
    }

    test("the published file gets the permissions of any file created there, not a temporary file's private ones") {
        val directory = tempdir().toPath()
        val published = PublishedModelFile(directory)
        published.save(demo)
        published.save(demo)
        val probe = Files.createFile(directory.resolve("probe"))
        Files.getPosixFilePermissions(published.file) shouldBe Files.getPosixFilePermissions(probe)
        Files.getPosixFilePermissions(published.backup) shouldBe Files.getPosixFilePermissions(probe)
    }

    test("a published file that cannot be read stops the start with the reader's reason and the way out") {
        val published = PublishedModelFile(tempdir().toPath())
        published.save(demo)
        Files.writeString(published.file, "<model")

        val error = shouldThrow<ModelFileException> { PlantModelLoader.loadAtStart(null, published) }

        error.message shouldContain published.file.toString()
        error.message shouldContain published.backup.toString()
        error.message shouldContain "--model FILE"
    }
})
