plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":extension-api"))
    implementation(libs.kotlinx.serialization.json)
    testImplementation(project(":kernel"))
    testImplementation(project(":adapters-loopback"))
    testImplementation(libs.playwright)
}

// The browser tests drive Debian's Chromium with the system's node; the 193 MB driver-bundle is not needed.
configurations.testRuntimeClasspath {
    exclude(group = "com.microsoft.playwright", module = "driver-bundle")
}

tasks.test {
    environment("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1")
    systemProperty("playwright.nodejs.path", "/usr/bin/node")
}
