// The root project only groups the modules. What the parent pom gives every module (Kotlin on JVM 17,
// kotlinx.serialization, Kotest on the JUnit Platform) is the convention plugin
// buildSrc/src/main/kotlin/ktcs.kotlin-jvm.gradle.kts, which each module applies.
plugins {
    base
}
