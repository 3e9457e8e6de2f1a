plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    testImplementation(project(":kernel"))
    testImplementation(project(":adapters-loopback"))
    testImplementation(project(":web-overview"))
    testImplementation(project(":xml-channels"))
    testImplementation(project(":adapters-vda5050"))
    testImplementation(project(":examples:tcp-vehicle-driver"))
    testImplementation(project(":examples:overview-panel-theme"))
    testImplementation(libs.playwright)
}

// The whole-plant test drives Debian's Chromium with the system's node; the 193 MB driver-bundle is not needed.
configurations.testRuntimeClasspath {
    exclude(group = "com.microsoft.playwright", module = "driver-bundle")
}

tasks.test {
    // BuildFilesAgreeTest reads the build files from here (Maven sets the same property in e2e-tests/pom.xml).
    systemProperty("ktcs.repositoryRoot", rootDir.absolutePath)
    environment("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1")
    systemProperty("playwright.nodejs.path", "/usr/bin/node")
}
