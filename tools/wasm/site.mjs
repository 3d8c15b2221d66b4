console.log("site: todo")
