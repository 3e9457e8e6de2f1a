// What the parent pom gives every module: Kotlin on JVM 17 with the kotlinx.serialization compiler plugin,
// Kotest on the JUnit Platform, and the same artifact names (ktcs-<module>).
// The Kotlin plugin adds kotlin-stdlib itself, matching the parent pom's kotlin-stdlib dependency.
// java-library provides api(...), which stands for Maven's compile scope: transitive to dependent modules.
plugins {
    `java-library`
    id("org.jetbrains.kotlin.jvm")
    id("org.jetbrains.kotlin.plugin.serialization")
}

group = "org.ktcs"
version = "0.1.0-SNAPSHOT"

base {
    archivesName.set("ktcs-${project.name}")
}

kotlin {
    jvmToolchain(17)
    // As the parent pom's javaParameters: Jackson binds Kotlin classes by their constructors' parameter names.
    compilerOptions {
        javaParameters.set(true)
    }
}

// Precompiled script plugins get no type-safe `libs` accessor, so the catalog is looked up by alias.
val libs = extensions.getByType<VersionCatalogsExtension>().named("libs")

dependencies {
    testImplementation(libs.findLibrary("kotest-runner-junit5").get())
    testImplementation(libs.findLibrary("kotest-assertions-core").get())
    testImplementation(libs.findLibrary("kotest-property").get())
}

tasks.withType<Test>().configureEach {
    useJUnitPlatform()
    // As the surefire argLine: keeps MockK's agent from warning about CDS and dynamic loading.
    jvmArgs("-Xshare:off", "-XX:+EnableDynamicAgentLoading")
}
