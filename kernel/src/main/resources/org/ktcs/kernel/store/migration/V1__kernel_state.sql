-- kTCS's state store (issue #18). One row per object, its current value as JSON in `body`; SQLite and PostgreSQL
-- read the same schema. The plant model is not here: it lives in kernel.dataDirectory/plant-model.xml.
CREATE TABLE transport_orders (name VARCHAR(1024) PRIMARY KEY, body TEXT NOT NULL);
CREATE TABLE order_sequences (name VARCHAR(1024) PRIMARY KEY, body TEXT NOT NULL);
CREATE TABLE vehicles (name VARCHAR(1024) PRIMARY KEY, body TEXT NOT NULL);
CREATE TABLE plant_locks (name VARCHAR(1024) PRIMARY KEY, body TEXT NOT NULL);
CREATE TABLE notifications (name VARCHAR(32) PRIMARY KEY, body TEXT NOT NULL);
CREATE TABLE kernel_values (name VARCHAR(64) PRIMARY KEY, body TEXT NOT NULL);
