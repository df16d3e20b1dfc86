// grape — what an animation writes to, and what the user must guarantee for each form.
//
// Raw (`T& object`): the engine keeps the object's address and writes there on every update.
//   The object must stay alive and in place (not moved, not in a std::vector that grows)
//   until the animation has completed or been killed: kill its animations before it goes
//   (Engine::kill_animations_of) or use one of the linked forms.
// Linked: the engine asks where the object is at every update and stops the animation
//   cleanly (no write, no event, killed) once the answer is "gone":
//   - `std::shared_ptr<T>`: the engine keeps a weak_ptr; the animation stops once the last
//     shared_ptr is gone. (The object must not die on another thread during a tick.)
//   - an object that derives from `grape::Animated` (or any object plus an `AnimationLink`
//     it owns, through `grape::linked(object, link)`): the animation stops once the link is
//     destroyed, so a plain member ends its object's animations with it. A copy or a move of
//     the object has a link of its own: animations stay with the object they were made for.
//   - `grape::element(vector, index)`: element `index` of a std::vector, found afresh at
//     every update, so the vector may grow and reallocate; the animation stops once the index
//     is past the end. The vector object itself must outlive the animation.
//   - `grape::accessor<T>(function)`: `function()` returns where the object is now, or
//     nullptr once it is gone (an entity looked up by id in your own registry).
// A linked animation whose target is gone stops at its next update (tick or seek); until
// then it counts in Engine::size() and its handle is alive.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace grape {

/// \addtogroup value
/// @{

namespace detail {
/// Where a linked target is now (nullptr: gone). The engine owns one per linked animation.
struct TargetRef {
    virtual ~TargetRef() = default;
    virtual void* get() noexcept = 0;
};
}  // namespace detail

/// A lifetime token an object owns: animations linked to it stop once it is destroyed.
/// Copies and moves make a fresh token (the new object's animations are its own). Costs one
/// pointer until the first animation links to it.
class AnimationLink {
public:
    AnimationLink() noexcept = default;
    /// A fresh token: the copy's animations are its own.
    AnimationLink(const AnimationLink&) noexcept {}
    /// Keeps this token: assigning an object does not move its animations.
    AnimationLink& operator=(const AnimationLink&) noexcept { return *this; }
    ~AnimationLink() {
        if (alive_) *alive_ = false;
    }
    /// The flag linked animations watch (made on first use).
    std::shared_ptr<const bool> watch() const {
        if (!alive_) alive_ = std::make_shared<bool>(true);
        return alive_;
    }

private:
    mutable std::shared_ptr<bool> alive_;
};

/// A base class for objects whose animations end with them: animations of a T derived from
/// Animated (bound as `engine.animate(object, ...)` or `create_2d_animation(object, ...)`)
/// are linked to it automatically.
class Animated {
public:
    /// The object's lifetime token.
    const AnimationLink& animation_link() const noexcept { return link_; }

private:
    AnimationLink link_;
};

/// An object together with the token it owns: its animations stop when the token goes.
template <class T>
struct Linked {
    T* object;  ///< the object written to
    const AnimationLink* link;  ///< the token it owns; must live as long as the object
};
/// `object`, linked to `link` (usually a member of object).
template <class T>
Linked<T> linked(T& object, const AnimationLink& link) noexcept {
    return {&object, &link};
}

/// Element `index` of `vector`, found at every update (survives reallocation).
template <class T, class Alloc>
struct Element {
    std::vector<T, Alloc>* vector;  ///< the vector, which must outlive the animation
    std::size_t index;  ///< the element; the animation stops once index ≥ size()
};
/// Binds element `index` of `vector` (the vector must outlive the animation).
template <class T, class Alloc>
Element<T, Alloc> element(std::vector<T, Alloc>& vector, std::size_t index) noexcept {
    return {&vector, index};
}

/// An object found by a function at every update (nullptr: gone).
template <class T>
struct Accessor {
    std::function<T*()> find;  ///< returns the object, or nullptr once it is gone
};
/// Binds the object `find()` returns at each update.
template <class T, class F>
Accessor<T> accessor(F find) {
    return {std::function<T*()>(std::move(find))};
}

namespace detail {

template <class T>
struct WeakRef final : TargetRef {
    std::weak_ptr<T> object;
    explicit WeakRef(const std::shared_ptr<T>& p) : object(p) {}
    void* get() noexcept override { return object.lock().get(); }
};
template <class T>
struct LinkRef final : TargetRef {
    T* object;
    std::shared_ptr<const bool> alive;
    LinkRef(T* o, std::shared_ptr<const bool> a) : object(o), alive(std::move(a)) {}
    void* get() noexcept override { return *alive ? object : nullptr; }
};
template <class T, class Alloc>
struct ElementRef final : TargetRef {
    std::vector<T, Alloc>* vector;
    std::size_t index;
    ElementRef(std::vector<T, Alloc>* v, std::size_t i) : vector(v), index(i) {}
    void* get() noexcept override { return index < vector->size() ? vector->data() + index : nullptr; }
};
template <class T>
struct AccessorRef final : TargetRef {
    std::function<T*()> find;
    explicit AccessorRef(std::function<T*()> f) : find(std::move(f)) {}
    void* get() noexcept override { return find ? static_cast<void*>(find()) : nullptr; }
};

/// What a target form binds: the object type, where it is now, and how to follow it.
template <class Form>
struct TargetForm {  // raw: T&
    using object_type = Form;
    static constexpr bool linked = std::is_base_of_v<Animated, Form>;
    static Form* now(Form& f) noexcept { return &f; }
    static std::unique_ptr<TargetRef> ref(Form& f) {
        if constexpr (linked) {
            return std::make_unique<LinkRef<Form>>(&f, static_cast<const Animated&>(f).animation_link().watch());
        } else {
            return nullptr;
        }
    }
};
template <class T>
struct TargetForm<std::shared_ptr<T>> {
    using object_type = T;
    static constexpr bool linked = true;
    static T* now(const std::shared_ptr<T>& p) noexcept { return p.get(); }
    static std::unique_ptr<TargetRef> ref(const std::shared_ptr<T>& p) { return std::make_unique<WeakRef<T>>(p); }
};
template <class T>
struct TargetForm<Linked<T>> {
    using object_type = T;
    static constexpr bool linked = true;
    static T* now(const Linked<T>& l) noexcept { return l.object; }
    static std::unique_ptr<TargetRef> ref(const Linked<T>& l) {
        return std::make_unique<LinkRef<T>>(l.object, l.link->watch());
    }
};
template <class T, class Alloc>
struct TargetForm<Element<T, Alloc>> {
    using object_type = T;
    static constexpr bool linked = true;
    static T* now(const Element<T, Alloc>& e) noexcept {
        return e.index < e.vector->size() ? e.vector->data() + e.index : nullptr;
    }
    static std::unique_ptr<TargetRef> ref(const Element<T, Alloc>& e) {
        return std::make_unique<ElementRef<T, Alloc>>(e.vector, e.index);
    }
};
template <class T>
struct TargetForm<Accessor<T>> {
    using object_type = T;
    static constexpr bool linked = true;
    static T* now(const Accessor<T>& a) { return a.find ? a.find() : nullptr; }
    static std::unique_ptr<TargetRef> ref(const Accessor<T>& a) { return std::make_unique<AccessorRef<T>>(a.find); }
};

/// A linked form other than a plain reference (shared_ptr, Linked, Element, Accessor).
template <class Form>
concept wrapped_target = requires { typename TargetForm<Form>::object_type; } &&
                         !std::is_same_v<typename TargetForm<Form>::object_type, Form>;

}  // namespace detail

/// @}

}  // namespace grape
