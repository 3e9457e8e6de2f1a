plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    testImplementation(project(":kernel"))
    testImplementation(project(":adapters-loopback"))
    testImplementation(project(":web-overview"))
    testImplementation(project(":xml-channels"))
    testImplementation(project(":examples:tcp-vehicle-driver"))
}

tasks.test {
    // BuildFilesAgreeTest reads the build files from here (Maven sets the same property in e2e-tests/pom.xml).
    systemProperty("ktcs.repositoryRoot", rootDir.absolutePath)
}
